// A 3-D spatial hash of points that answers "is any point within r of p?" — the separation
// test of evenly spaced streamlines (Jobard & Lefer 1997, "Creating Evenly-Spaced Streamlines
// of Arbitrary Density"), which hatching asks at every step of every stroke it traces.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>

namespace inkshade::geometry {

// Cubic cells of one size; an open-addressing table from a cell to the head of its list of
// points, the lists threaded through one array, so adding a point allocates nothing but the
// arrays' growth. Points are kept in float.
class PointGrid {
public:
    explicit PointGrid(double cell);

    void add(const glm::dvec3& p);
    // The points along a segment, at most `spacing` apart; `with_start` false leaves out its
    // first point (the previous segment's last: stored twice it would only lengthen the lists
    // the queries walk).
    void add_segment(const glm::dvec3& a, const glm::dvec3& b, double spacing, bool with_start = true);

    // Whether some point lies within r (≤ the cell size) of p, in float arithmetic (the
    // squared distance below r²).
    bool any_within(const glm::dvec3& p, double r) const;

    size_t size() const { return points_.size(); }

private:
    struct Slot {
        uint64_t key = kEmpty;
        uint32_t head = kNoPoint;
    };
    struct Entry {
        glm::vec3 p;
        uint32_t next;  // the next point of the cell's list
    };
    static constexpr uint64_t kEmpty = ~uint64_t(0);
    static constexpr uint32_t kNoPoint = 0xffffffffu;

    glm::i64vec3 cell_of(const glm::dvec3& p) const { return glm::i64vec3(glm::floor(p / cell_)); }
    static uint64_t key(const glm::i64vec3& c);
    size_t slot_of(uint64_t k) const;
    Slot& find(uint64_t k);
    uint32_t lookup(uint64_t k) const;
    bool near_in(const glm::i64vec3& c, const glm::vec3& p, float r2) const;
    void rehash(size_t capacity);

    double cell_;
    std::vector<Slot> slots_;
    int shift_ = 64;
    size_t used_ = 0;
    std::vector<Entry> points_;
};

}  // namespace inkshade::geometry
