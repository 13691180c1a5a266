#include "geometry/weld.hpp"

#include <gtest/gtest.h>

#include <array>

#include "inkshade/mesh_stats.hpp"

namespace inkshade::geometry {
namespace {

// A unit cube as an STL-style soup: 12 triangles, 36 vertices, every corner repeated.
Mesh cube_soup() {
    const std::array<glm::vec3, 8> c = {
        {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
    const std::array<glm::uvec3, 12> tris = {{{0, 2, 1},
                                              {0, 3, 2},
                                              {4, 5, 6},
                                              {4, 6, 7},
                                              {0, 1, 5},
                                              {0, 5, 4},
                                              {1, 2, 6},
                                              {1, 6, 5},
                                              {2, 3, 7},
                                              {2, 7, 6},
                                              {3, 0, 4},
                                              {3, 4, 7}}};
    Mesh m;
    for (const glm::uvec3& t : tris) {
        const auto base = uint32_t(m.positions.size());
        for (int k = 0; k < 3; ++k) m.positions.push_back(c[t[k]]);
        m.triangles.emplace_back(base, base + 1, base + 2);
    }
    return m;
}

TEST(Weld, StlCubeSoupBecomesEightVertices) {
    Mesh m = cube_soup();
    ASSERT_EQ(m.vertex_count(), 36u);
    weld(m);
    EXPECT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_TRUE(m.welded);
    const MeshStats s = mesh_stats(m);
    EXPECT_EQ(s.boundary_edges, 0u);
    EXPECT_EQ(s.euler_characteristic, 2);
}

TEST(Weld, TrianglesKeepTheirCorners) {
    Mesh m = cube_soup();
    const Mesh before = m;
    weld(m);
    for (size_t f = 0; f < m.triangle_count(); ++f)
        for (int k = 0; k < 3; ++k) EXPECT_EQ(m.positions[m.triangles[f][k]], before.positions[before.triangles[f][k]]);
}

TEST(Weld, FirstVertexAttributesAreKept) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}};
    m.triangles = {{0, 1, 2}, {3, 2, 1}};
    m.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    weld(m);
    ASSERT_EQ(m.vertex_count(), 3u);
    ASSERT_EQ(m.colors.size(), 3u);
    EXPECT_EQ(m.colors[0], glm::vec3(1, 0, 0));
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 1));
}

TEST(Weld, NearCoincidentWithinEpsilonMerge) {
    Mesh m;
    // Diagonal is sqrt(2); a 1e-7 offset is well within 1e-6 * diagonal.
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1e-7f, 0, 0}, {1, 1e-7f, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}, {3, 4, 5}};
    weld(m);
    EXPECT_EQ(m.vertex_count(), 3u);
    EXPECT_TRUE(m.welded);
}

TEST(Weld, BeyondEpsilonStaysApart) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1e-4f, 0, 0}, {1, 1e-4f, 0}, {0, 1.0001f, 0}};
    m.triangles = {{0, 1, 2}, {3, 4, 5}};
    weld(m);
    EXPECT_EQ(m.vertex_count(), 6u);
    EXPECT_FALSE(m.welded);
}

TEST(Weld, LargerRelativeEpsilonMergesMore) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1e-4f, 0, 0}};
    m.triangles = {{0, 1, 2}, {3, 1, 2}};
    weld(m, {.relative_epsilon = 1e-3f});
    EXPECT_EQ(m.vertex_count(), 3u);
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 1, 2));
}

TEST(Weld, CollapsedTrianglesAreKept) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}};
    m.triangles = {{0, 1, 2}, {0, 3, 1}};
    weld(m);
    ASSERT_EQ(m.triangle_count(), 2u);
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 0, 1));
}

TEST(Weld, EmptyMeshIsUnchanged) {
    Mesh m;
    weld(m);
    EXPECT_EQ(m.vertex_count(), 0u);
    EXPECT_FALSE(m.welded);
}

TEST(Weld, AllPointsCoincidentMergeToOne) {
    Mesh m;
    m.positions = {{2, 2, 2}, {2, 2, 2}, {2, 2, 2}};
    m.triangles = {{0, 1, 2}};
    weld(m);
    EXPECT_EQ(m.vertex_count(), 1u);
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 0, 0));
}

TEST(Weld, NonFiniteVertexNeverMerges) {
    Mesh m;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    m.positions = {{0, 0, 0}, {1, 0, 0}, {nan, 0, 0}, {nan, 0, 0}, {0, 0, 0}};
    m.triangles = {{0, 1, 2}, {4, 1, 3}};
    weld(m);
    EXPECT_EQ(m.vertex_count(), 4u);
}

TEST(Weld, LargeGridSoupWeldsToSharedVertices) {
    // 200 x 200 quads as a soup: (n+1)^2 shared vertices once welded.
    const int n = 200;
    Mesh m;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::vec3 a(i, j, 0), b(i + 1, j, 0), c(i + 1, j + 1, 0), d(i, j + 1, 0);
            for (const glm::vec3& q : {a, b, c, a, c, d}) m.positions.push_back(q);
            const auto base = uint32_t(m.positions.size() - 6);
            m.triangles.emplace_back(base, base + 1, base + 2);
            m.triangles.emplace_back(base + 3, base + 4, base + 5);
        }
    weld(m);
    EXPECT_EQ(m.vertex_count(), size_t((n + 1) * (n + 1)));
    const MeshStats s = mesh_stats(m);
    EXPECT_EQ(s.boundary_edges, size_t(4 * n));
    EXPECT_EQ(s.euler_characteristic, 1);
}

}  // namespace
}  // namespace inkshade::geometry
