#include "geometry/point_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace inkshade::geometry {

PointGrid::PointGrid(double cell) : cell_(cell) { rehash(1024); }

void PointGrid::add(const glm::dvec3& p) {
    if (2 * (used_ + 1) > slots_.size()) rehash(2 * slots_.size());
    Slot& slot = find(key(cell_of(p)));
    if (slot.head == kNoPoint) ++used_;
    points_.push_back({glm::vec3(p), slot.head});
    slot.head = uint32_t(points_.size() - 1);
}

void PointGrid::add_segment(const glm::dvec3& a, const glm::dvec3& b, double spacing, bool with_start) {
    const int n = std::max(1, int(std::ceil(glm::length(b - a) / spacing)));
    for (int i = with_start ? 0 : 1; i <= n; ++i) add(a + (b - a) * (double(i) / n));
}

bool PointGrid::near_in(const glm::i64vec3& c, const glm::vec3& p, float r2) const {
    for (uint32_t i = lookup(key(c)); i != kNoPoint; i = points_[i].next) {
        const glm::vec3 d = points_[i].p - p;
        if (glm::dot(d, d) < r2) return true;
    }
    return false;
}

// The cells that the box of radius r around p touches (two or three a side), p's own cell
// first (where a point is most likely), skipping those whose box is farther than r (the
// corners of a 3 × 3 × 3 block mostly are).
bool PointGrid::any_within(const glm::dvec3& p, double r) const {
    const glm::i64vec3 lo = cell_of(p - glm::dvec3(r)), hi = cell_of(p + glm::dvec3(r)), home = cell_of(p);
    const float r2 = float(r * r);
    const glm::vec3 pf(p);
    if (near_in(home, pf, r2)) return true;
    // Points and the query are compared in float, so a point that counts may lie about a
    // float rounding step (2^-24 of the coordinates) farther than r from p in exact terms:
    // the boxes are tested grown by `slack`, far more than that.
    const double slack = 1e-5 * (cell_ + std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
    const double reach2 = (r + slack) * (r + slack);
    auto gap2 = [&](int64_t c, double v) {
        const double g = std::max({double(c) * cell_ - v, v - double(c + 1) * cell_, 0.0});
        return g * g;
    };
    for (int64_t z = lo.z; z <= hi.z; ++z) {
        const double gz = gap2(z, p.z);
        for (int64_t y = lo.y; y <= hi.y; ++y) {
            const double gyz = gz + gap2(y, p.y);
            if (gyz > reach2) continue;
            for (int64_t x = lo.x; x <= hi.x; ++x) {
                const glm::i64vec3 c(x, y, z);
                if (c == home || gyz + gap2(x, p.x) > reach2) continue;
                if (near_in(c, pf, r2)) return true;
            }
        }
    }
    return false;
}

// 21 bits a coordinate (cells wrap beyond ±2^20: only more points per list, never a miss).
uint64_t PointGrid::key(const glm::i64vec3& c) {
    return (uint64_t(c.x & 0x1fffff) << 42) | (uint64_t(c.y & 0x1fffff) << 21) | uint64_t(c.z & 0x1fffff);
}

// Fibonacci hashing: the product's top bits depend on every bit of the key (its low bits only
// on the key's low bits, which left cells differing in x alone in one probe run).
size_t PointGrid::slot_of(uint64_t k) const { return size_t((k * 0x9e3779b97f4a7c15ull) >> shift_); }

PointGrid::Slot& PointGrid::find(uint64_t k) {
    for (size_t h = slot_of(k);; h = (h + 1) & (slots_.size() - 1))
        if (slots_[h].key == k || slots_[h].key == kEmpty) {
            slots_[h].key = k;
            return slots_[h];
        }
}

uint32_t PointGrid::lookup(uint64_t k) const {
    for (size_t h = slot_of(k);; h = (h + 1) & (slots_.size() - 1)) {
        if (slots_[h].key == k) return slots_[h].head;
        if (slots_[h].key == kEmpty) return kNoPoint;
    }
}

void PointGrid::rehash(size_t capacity) {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(capacity, Slot{});
    shift_ = 64 - std::countr_zero(capacity);
    for (const Slot& s : old)
        if (s.key != kEmpty) find(s.key).head = s.head;
}

}  // namespace inkshade::geometry
