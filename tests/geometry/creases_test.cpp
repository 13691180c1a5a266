#include "geometry/creases.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"

namespace inkshade::geometry {
namespace {

// Unit cube, 8 shared corners, two triangles per side (counter-clockwise seen from outside).
Mesh cube() {
    Mesh m;
    for (int i = 0; i < 8; ++i) m.positions.emplace_back(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        m.triangles.emplace_back(q[0], q[1], q[2]);
        m.triangles.emplace_back(q[0], q[2], q[3]);
    }
    return m;
}

// An L-shaped prism (a fandisk-like block with one concave fold): the L polygon
// (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), reflex corner at (1,1), extruded over z ∈ [0, 1]. Caps
// are fans from the reflex corner (the L is star-shaped about it), sides two triangles each.
Mesh l_prism() {
    const glm::vec2 l[6] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    Mesh m;
    for (int z = 0; z < 2; ++z)
        for (const glm::vec2& p : l) m.positions.emplace_back(p.x, p.y, float(z));
    for (int k = 0; k < 4; ++k) {
        const uint32_t a = 3, b = uint32_t((4 + k) % 6), c = uint32_t((5 + k) % 6);
        m.triangles.emplace_back(a + 6, b + 6, c + 6);  // top, counter-clockwise from +z
        m.triangles.emplace_back(a, c, b);              // bottom, reversed
    }
    for (uint32_t i = 0; i < 6; ++i) {
        const uint32_t j = (i + 1) % 6;
        m.triangles.emplace_back(i, j, j + 6);
        m.triangles.emplace_back(i, j + 6, i + 6);
    }
    return m;
}

Mesh grid(int nx, int ny) {
    Mesh m;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) m.positions.emplace_back(float(i), float(j), 0.0f);
    const auto idx = [&](int i, int j) { return uint32_t(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            m.triangles.emplace_back(idx(i, j), idx(i + 1, j), idx(i + 1, j + 1));
            m.triangles.emplace_back(idx(i, j), idx(i + 1, j + 1), idx(i, j + 1));
        }
    return m;
}

CreaseLines creases(const Mesh& m, const CreaseOptions& options = {}) {
    return extract_creases(m, build_edge_adjacency(m), options);
}

// Number of coordinates in which a and b differ: 1 for a cube side, 2 for a face diagonal.
int differing_axes(const glm::vec3& a, const glm::vec3& b) {
    return int(a.x != b.x) + int(a.y != b.y) + int(a.z != b.z);
}

TEST(Creases, CubeCreasesAreExactlyTheTwelveSides) {
    const Mesh m = cube();
    const CreaseLines c = creases(m);
    EXPECT_EQ(c.ridges.size(), 12u);
    EXPECT_TRUE(c.valleys.empty());
    EXPECT_TRUE(c.borders.empty());
    EXPECT_TRUE(c.non_manifold.empty());
    std::set<std::pair<uint64_t, uint64_t>> seen;
    for (const LineSegment& s : c.ridges) {
        EXPECT_EQ(differing_axes(s.a, s.b), 1);  // a side, never a diagonal
        EXPECT_EQ(s.strength_a, 1.0f);
        EXPECT_EQ(s.strength_b, 1.0f);
        seen.insert({s.edge_a, s.edge_b});
    }
    EXPECT_EQ(seen.size(), 12u);
    // Every corner joins three creases, so chains end at corners: twelve single edges.
    const auto lines = chain_segments(c.ridges);
    ASSERT_EQ(lines.size(), 12u);
    for (const Polyline& l : lines) {
        EXPECT_FALSE(l.closed);
        EXPECT_EQ(l.points.size(), 2u);
    }
    // A 100° limit leaves nothing on a box (90° folds).
    EXPECT_TRUE(creases(m, {.angle_degrees = 100.0f}).ridges.empty());
}

TEST(Creases, LPrismReflexEdgeIsTheOnlyValley) {
    const Mesh m = l_prism();
    const CreaseLines c = creases(m);
    ASSERT_EQ(c.valleys.size(), 1u);
    // The vertical edge through the reflex corner (1, 1).
    EXPECT_EQ(glm::vec2(c.valleys[0].a), glm::vec2(1, 1));
    EXPECT_EQ(glm::vec2(c.valleys[0].b), glm::vec2(1, 1));
    EXPECT_EQ(c.ridges.size(), 17u);  // 5 convex verticals + 6 top + 6 bottom outline edges
    EXPECT_TRUE(c.borders.empty());
    for (const LineSegment& s : c.ridges) EXPECT_EQ(differing_axes(s.a, s.b), 1);
    // Turning the surface inside out swaps ridges and valleys.
    Mesh flipped = m;
    for (glm::uvec3& t : flipped.triangles) std::swap(t.y, t.z);
    const CreaseLines f = creases(flipped);
    EXPECT_EQ(f.ridges.size(), 1u);
    EXPECT_EQ(f.valleys.size(), 17u);
}

TEST(Creases, FoldAngleAgainstThreshold) {
    // Two triangles sharing edge (0, 1) on the x axis, the second folded down by `fold` degrees.
    const auto hinge = [](float fold) {
        Mesh m;
        const float a = glm::radians(fold);
        m.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -std::cos(a), -std::sin(a)}};
        m.triangles = {{0, 1, 2}, {1, 0, 3}};
        return m;
    };
    EXPECT_TRUE(creases(hinge(50.0f)).ridges.empty());
    EXPECT_EQ(creases(hinge(70.0f)).ridges.size(), 1u);
    EXPECT_EQ(creases(hinge(50.0f), {.angle_degrees = 40.0f}).ridges.size(), 1u);
    // Folded up instead: concave.
    const CreaseLines up = creases(hinge(-70.0f));
    EXPECT_TRUE(up.ridges.empty());
    EXPECT_EQ(up.valleys.size(), 1u);
    // Both open sides are borders: four.
    EXPECT_EQ(creases(hinge(70.0f)).borders.size(), 4u);
    // Inconsistent orientation of a flat pair is no crease.
    Mesh seam = hinge(0.0f);
    seam.triangles[1] = {0, 1, 3};
    EXPECT_TRUE(creases(seam).ridges.empty());
    EXPECT_TRUE(creases(seam).valleys.empty());
}

TEST(Creases, OpenGridBorderChainsIntoOneClosedLoop) {
    const int nx = 9, ny = 5;
    const Mesh m = grid(nx, ny);
    const CreaseLines c = creases(m);
    EXPECT_TRUE(c.ridges.empty());
    EXPECT_TRUE(c.valleys.empty());
    ASSERT_EQ(c.borders.size(), size_t(2 * (nx + ny)));
    const auto lines = chain_segments(c.borders);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(lines[0].closed);
    ASSERT_EQ(lines[0].points.size(), size_t(2 * (nx + ny)));
    std::set<std::pair<float, float>> distinct;
    for (const glm::vec3& p : lines[0].points) {
        EXPECT_TRUE(p.x == 0 || p.x == nx || p.y == 0 || p.y == ny) << p.x << "," << p.y;
        distinct.insert({p.x, p.y});
    }
    EXPECT_EQ(distinct.size(), lines[0].points.size());
    EXPECT_NEAR(polyline_length(lines[0]), 2.0f * (nx + ny), 1e-4f);
}

TEST(Creases, SmoothSphereHasNone) {
    const CreaseLines c = creases(builtin::sphere(32, 64, 1.0f));
    EXPECT_TRUE(c.ridges.empty());
    EXPECT_TRUE(c.valleys.empty());
    EXPECT_TRUE(c.borders.empty());
    EXPECT_TRUE(c.non_manifold.empty());
}

TEST(Creases, BadMeshesGiveResultsWithoutCrashing) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0}, {0.5f, 0, 1},
                   {2, 2, 2}, {0, 0, 0}, {NAN, 0, 0},  {9, 9, 9}};
    m.triangles = {{0, 1, 2}, {1, 0, 3},  {0, 1, 4},  // non-manifold edge (0, 1)
                   {1, 1, 2}, {0, 1, 99},             // repeated, out of range
                   {2, 4, 6}, {0, 6, 2},              // 6 sits on 0: zero area
                   {3, 4, 7}};                        // a NaN corner
    const CreaseLines c = creases(m);
    ASSERT_EQ(c.non_manifold.size(), 1u);
    EXPECT_EQ(c.non_manifold[0].edge_a, vertex_key(0));
    EXPECT_EQ(c.non_manifold[0].edge_b, vertex_key(1));
    for (const auto* list : {&c.ridges, &c.valleys, &c.borders})
        for (const LineSegment& s : *list) {
            EXPECT_NE(s.edge_a, s.edge_b);
            EXPECT_LT(s.face, m.triangles.size());
        }
    EXPECT_FALSE(c.borders.empty());
    // All lists chain without trouble.
    for (const auto* list : {&c.ridges, &c.valleys, &c.borders, &c.non_manifold}) (void)chain_segments(*list);
    EXPECT_TRUE(creases(Mesh{}).borders.empty());
}

}  // namespace
}  // namespace inkshade::geometry
