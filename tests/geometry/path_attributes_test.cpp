#include "geometry/path_attributes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "geometry/chain_split.hpp"
#include "geometry/path_arc_length.hpp"
#include "geometry/stroke_coherence.hpp"
#include "stroke_paths.hpp"

namespace inkshade::geometry {
namespace {

// Every attribute a linear function of the point, so that interpolating between points keeps
// it: wherever an operation puts a point, its attributes can be checked against it.
float depth_at(glm::vec2 p) { return 0.001f * p.x + 0.002f * p.y; }
float strength_at(glm::vec2 p) { return 0.003f * p.x + 0.001f * p.y; }
float width_at(glm::vec2 p) { return 1.0f + 0.01f * p.x + 0.02f * p.y; }
glm::vec3 color_at(glm::vec2 p) { return {0.001f * p.x, 0.001f * p.y, 0.001f * (p.x + p.y)}; }
glm::vec3 world_at(glm::vec2 p) { return {p.x, p.y, p.x - p.y}; }
constexpr float kUOffset = 7.0f;

// `p` with every per-point attribute set; u = kUOffset + arc length; each surface point's face
// the index of the piece from it to the next point (the last point of an open path: of the
// piece ending there), w = 1 so that the surface point is linear in the image too.
LinePath filled(LinePath p) {
    p.depth.clear();
    p.strength.clear();
    for (glm::vec2 q : p.points) {
        p.depth.push_back(depth_at(q));
        p.strength.push_back(strength_at(q));
        p.width.push_back(width_at(q));
        p.color.push_back(color_at(q));
        p.world.push_back(world_at(q));
        p.surface.push_back({.world = world_at(q), .face = int32_t(p.surface.size()), .barycentric = {}, .w = 1.0f});
    }
    if (!p.closed && p.surface.size() > 1) p.surface.back().face = int32_t(p.surface.size()) - 2;
    const std::vector<double> s = arc_lengths(p);
    for (size_t i = 0; i < p.points.size(); ++i) p.u.push_back(float(kUOffset + s[i]));
    p.level = 3;
    return p;
}

bool near(float a, float b) { return std::abs(a - b) <= 1e-4f * std::max(1.0f, std::abs(b)); }
bool near(glm::vec3 a, glm::vec3 b) { return near(a.x, b.x) && near(a.y, b.y) && near(a.z, b.z); }

// Every attribute present, of the points' size and at the value of its point; u (unless
// `u_dropped`) still offset + arc length from the path's start.
void expect_follows_points(const LinePath& p, bool u_dropped, const std::string& what) {
    SCOPED_TRACE(what);
    ASSERT_GE(p.points.size(), 2u);
    EXPECT_EQ(p.level, 3);
    size_t present = 0;
    auto check = [&](const auto& v) {
        if (v.empty()) return;
        ++present;
        EXPECT_EQ(v.size(), p.points.size());
    };
    for_each_point_attribute(check, p);
    EXPECT_EQ(present, u_dropped ? 7u : 8u);
    if (!attributes_consistent(p)) return;
    for (size_t i = 0; i < p.points.size(); ++i) {
        const glm::vec2 q = p.points[i];
        EXPECT_TRUE(near(p.depth[i], depth_at(q))) << i;
        EXPECT_TRUE(near(p.strength[i], strength_at(q))) << i;
        EXPECT_TRUE(near(p.width[i], width_at(q))) << i;
        EXPECT_TRUE(near(p.color[i], color_at(q))) << i;
        EXPECT_TRUE(near(p.world[i], world_at(q))) << i;
        EXPECT_TRUE(near(p.surface[i].world, world_at(q))) << i;
    }
    if (u_dropped) return;
    const std::vector<double> s = arc_lengths(p);
    for (size_t i = 1; i < p.points.size(); ++i)
        EXPECT_NEAR(double(p.u[i] - p.u[0]), s[i], 1e-3 * std::max(1.0, s[i])) << i;
}

float distance_to_piece(glm::vec2 q, const LinePath& original, int32_t piece) {
    const size_t n = original.points.size();
    const glm::vec2 a = original.points[size_t(piece)], b = original.points[(size_t(piece) + 1) % n];
    const float t = glm::clamp(glm::dot(q - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
    return glm::length(q - (a + (b - a) * t));
}

// Each surface point's face (a piece index of `original`, as filled() numbers them) is the piece
// the path goes on along from that point: the middle of the step to the next point (of the
// closing step of a loop) lies on it, and an open path's last point lies on its own.
void expect_faces_follow(const LinePath& p, const LinePath& original, const std::string& what) {
    SCOPED_TRACE(what);
    ASSERT_EQ(p.surface.size(), p.points.size());
    const size_t n = p.points.size();
    for (size_t k = 0; k < n; ++k) {
        const int32_t face = p.surface[k].face;
        ASSERT_GE(face, 0);
        ASSERT_LT(size_t(face), original.points.size());
        const bool last_open = !p.closed && k + 1 == n;
        const glm::vec2 q = last_open ? p.points[k] : 0.5f * (p.points[k] + p.points[(k + 1) % n]);
        EXPECT_LT(distance_to_piece(q, original, face), 1e-3f) << k << " of " << n;
    }
}

TEST(PathAttributes, VisitsEveryVectorOfLinePath) {
    LinePath p;
    std::set<const void*> seen;
    std::vector<const void*> order;
    auto note = [&](const auto& v) {
        seen.insert(&v);
        order.push_back(&v);
    };
    for_each_point_attribute(note, p);
    EXPECT_EQ(seen.size(), order.size());
    ASSERT_FALSE(order.empty());
    EXPECT_EQ(order.front(), &p.points);
    // LinePath is its per-point vectors, then `closed` and `level`: a vector added to it and not
    // to for_each_point_attribute makes it larger than this (all std::vectors are one size).
    struct NotPerPoint {
        bool closed;
        int level;
    };
    EXPECT_EQ(sizeof(LinePath), order.size() * sizeof(std::vector<float>) + sizeof(NotPerPoint))
        << "a LinePath member for_each_point_attribute does not visit (src/geometry/path_attributes.hpp)";
}

TEST(PathAttributes, VisitsSeveralPathsInStep) {
    const LinePath a = filled(test::straight_path({0, 0}, {10, 0}, 2.0f));
    LinePath b;
    for_each_point_attribute([](auto& to, const auto& from) { to = from; }, b, a);
    EXPECT_EQ(b.points, a.points);
    EXPECT_EQ(b.u, a.u);
    EXPECT_EQ(b.world, a.world);
    EXPECT_FALSE(b.closed);  // not per point: not visited
    EXPECT_EQ(b.level, 0);
}

TEST(PathAttributes, ConsistentWhenEachIsEmptyOrOfThePointsSize) {
    LinePath p = filled(test::straight_path({0, 0}, {10, 0}, 2.0f));
    EXPECT_TRUE(attributes_consistent(p));
    p.width.clear();
    EXPECT_TRUE(attributes_consistent(p));
    p.u.pop_back();
    EXPECT_FALSE(attributes_consistent(p));
}

TEST(PathAttributes, KeptByEveryPathOperation) {
    const LinePath line = filled(test::straight_path({10, 20}, {90, 60}, 3.0f));
    const LinePath loop = filled(test::square_path({20, 30}, 40.0f));
    expect_follows_points(line, false, "filled line");
    expect_follows_points(loop, false, "filled loop");

    expect_follows_points(opened(loop), false, "opened");
    expect_follows_points(rotated(loop, 17), false, "rotated");
    expect_follows_points(rotated_at(loop, 51.5), false, "rotated_at");
    const LinePath open = opened(loop);
    expect_follows_points(sub_path(open, arc_lengths(open), 12.25, 97.5), false, "sub_path");
    // Reversing keeps every attribute but u, which would decrease along the path.
    expect_follows_points(reversed(line), true, "reversed line");
    expect_follows_points(reversed(loop), true, "reversed loop");

    // Split at the square's corners (vertex ranges of the loop rotated and opened), and cut to
    // a length (sub-paths).
    const std::vector<LinePath> corners = split_chains({loop}, {.split_angle_degrees = 45.0f});
    EXPECT_EQ(corners.size(), 4u);
    for (const LinePath& piece : corners) expect_follows_points(piece, false, "split at a corner");
    const std::vector<LinePath> cut = split_chains({line, loop}, {.max_length_px = 25.0f});
    EXPECT_GT(cut.size(), 2u);
    for (const LinePath& piece : cut) expect_follows_points(piece, false, "cut to a length");
}

TEST(PathAttributes, SurfaceFacesStayOnTheirPieces) {
    // A loop whose corners are 10 px apart, so that a face is one piece of several pixels.
    LinePath loop;
    loop.closed = true;
    for (glm::vec2 c : {glm::vec2(0, 0), glm::vec2(40, 0), glm::vec2(40, 40), glm::vec2(0, 40)})
        loop.points.push_back(c);
    loop = filled(loop);
    LinePath line = filled(test::straight_path({10, 20}, {90, 60}, 9.0f));
    for (const LinePath* original : {&loop, &line}) {
        const LinePath& o = *original;
        const std::string kind = o.closed ? "loop " : "line ";
        expect_faces_follow(o, o, kind + "as filled");
        expect_faces_follow(reversed(o), o, kind + "reversed");
        expect_faces_follow(reversed(reversed(o)), o, kind + "reversed twice");
        expect_faces_follow(opened(o), o, kind + "opened");
        if (o.closed) expect_faces_follow(rotated(o, 3), o, kind + "rotated");  // a loop's operation
        expect_faces_follow(rotated_at(o, 51.5), o, kind + "rotated_at");
        const LinePath open = opened(o);
        expect_faces_follow(sub_path(open, arc_lengths(open), 12.25, 97.5), o, kind + "sub_path");
        expect_faces_follow(reversed(sub_path(open, arc_lengths(open), 12.25, 97.5)), o, kind + "reversed sub_path");
        for (const LinePath& piece : split_chains({o}, {.max_length_px = 7.0f}))
            expect_faces_follow(piece, o, kind + "cut to a length");
    }
}

}  // namespace
}  // namespace inkshade::geometry
