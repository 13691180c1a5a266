#include "geometry/adjacency.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>

#include "geometry/builtin_models.hpp"

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

// Flat (nx × ny)-quad grid in the z = 0 plane, two triangles per quad.
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

// The edge joining i and j, or edge_count() when there is none.
size_t find_edge(const EdgeAdjacency& adj, uint32_t i, uint32_t j) {
    const glm::uvec2 key(std::min(i, j), std::max(i, j));
    const auto it = std::lower_bound(adj.edges.begin(), adj.edges.end(), key, [](glm::uvec2 a, glm::uvec2 b) {
        return std::pair(a.x, a.y) < std::pair(b.x, b.y);
    });
    return it != adj.edges.end() && *it == key ? size_t(it - adj.edges.begin()) : adj.edge_count();
}

// Structural checks every adjacency must pass.
void expect_consistent(const Mesh& m, const EdgeAdjacency& adj) {
    ASSERT_EQ(adj.faces.size(), adj.edges.size());
    ASSERT_EQ(adj.flags.size(), adj.edges.size());
    size_t sides = 0;
    for (size_t e = 0; e < adj.edge_count(); ++e) {
        EXPECT_LT(adj.edges[e].x, adj.edges[e].y);
        if (e > 0) {
            EXPECT_LT(std::pair(adj.edges[e - 1].x, adj.edges[e - 1].y), std::pair(adj.edges[e].x, adj.edges[e].y));
        }
        EXPECT_GE(adj.face_count(e), 1u);
        EXPECT_EQ(adj.is_border(e), adj.face_count(e) == 1);
        EXPECT_EQ(adj.is_border(e), adj.faces[e].y == EdgeAdjacency::kNoFace);
        EXPECT_EQ(adj.is_non_manifold(e), adj.face_count(e) > 2);
        sides += adj.face_count(e);
        for (uint32_t k = 0; k < adj.face_count(e); ++k) {
            const uint32_t f = adj.face(e, k);
            if (k > 0) {
                EXPECT_LT(adj.face(e, k - 1), f);
            }
            // The face has this edge among its sides.
            ASSERT_LT(f, m.triangles.size());
            const glm::uvec3 t = m.triangles[f];
            bool found = false;
            for (int s = 0; s < 3; ++s)
                found |= glm::uvec2(std::min(t[s], t[(s + 1) % 3]), std::max(t[s], t[(s + 1) % 3])) == adj.edges[e];
            EXPECT_TRUE(found) << "edge " << e << " face " << f;
        }
    }
    EXPECT_TRUE(std::is_sorted(adj.more_faces.begin(), adj.more_faces.end(),
                               [](glm::uvec2 a, glm::uvec2 b) { return std::pair(a.x, a.y) < std::pair(b.x, b.y); }));
    // Every side of a usable face is an edge that lists the face: the lists cover all sides.
    size_t usable_sides = 0;
    for (size_t f = 0; f < m.triangles.size(); ++f) {
        const glm::uvec3 t = m.triangles[f];
        const size_t n = m.positions.size();
        if (t.x >= n || t.y >= n || t.z >= n || t.x == t.y || t.y == t.z || t.z == t.x) continue;
        for (int s = 0; s < 3; ++s) {
            ++usable_sides;
            const size_t e = find_edge(adj, t[s], t[(s + 1) % 3]);
            ASSERT_LT(e, adj.edge_count());
            bool listed = false;
            for (uint32_t k = 0; k < adj.face_count(e); ++k) listed |= adj.face(e, k) == f;
            EXPECT_TRUE(listed) << "face " << f << " side " << s;
        }
    }
    EXPECT_EQ(sides, usable_sides);
}

TEST(Adjacency, CubeHasEighteenManifoldEdges) {
    const Mesh m = cube();
    const EdgeAdjacency adj = build_edge_adjacency(m);
    expect_consistent(m, adj);
    EXPECT_EQ(adj.edge_count(), 18u);  // 12 sides + 6 diagonals; Euler: 8 − 18 + 12 = 2
    for (size_t e = 0; e < adj.edge_count(); ++e) {
        EXPECT_EQ(adj.face_count(e), 2u);
        EXPECT_EQ(adj.flags[e], 0);
    }
}

TEST(Adjacency, OpenGridBorderIsItsBoundary) {
    const int nx = 7, ny = 4;
    const Mesh m = grid(nx, ny);
    const EdgeAdjacency adj = build_edge_adjacency(m);
    expect_consistent(m, adj);
    // Horizontal + vertical + diagonal edges.
    EXPECT_EQ(adj.edge_count(), size_t(nx * (ny + 1) + (nx + 1) * ny + nx * ny));
    size_t border = 0;
    for (size_t e = 0; e < adj.edge_count(); ++e) {
        if (!adj.is_border(e)) continue;
        ++border;
        const glm::vec3 a = m.positions[adj.edges[e].x], b = m.positions[adj.edges[e].y];
        // Both ends on the same side of the rectangle.
        const bool on_x = (a.x == 0 && b.x == 0) || (a.x == nx && b.x == nx);
        const bool on_y = (a.y == 0 && b.y == 0) || (a.y == ny && b.y == ny);
        EXPECT_TRUE(on_x || on_y) << a.x << "," << a.y << " " << b.x << "," << b.y;
    }
    EXPECT_EQ(border, size_t(2 * (nx + ny)));
}

TEST(Adjacency, BadFacesAreSkippedAndNonManifoldFlagged) {
    Mesh m;
    m.positions = {{0, 0, 0},    {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0},
                   {0.5f, 0, 1}, {2, 2, 2}, {0, 0, 0},    {7, 7, 7}};  // 6 duplicates 0's position, 7 isolated
    m.triangles = {{0, 1, 2}, {1, 0, 3},  {0, 1, 4},                   // edge (0,1) has three faces
                   {1, 1, 2}, {0, 1, 99}, {5, 5, 5},                   // repeated and out-of-range indices
                   {0, 6, 1}};                                         // zero area, distinct indices: kept
    const EdgeAdjacency adj = build_edge_adjacency(m);
    expect_consistent(m, adj);
    // Faces 3, 4 and 5 have no edges: no edge lists them.
    for (size_t e = 0; e < adj.edge_count(); ++e)
        for (uint32_t k = 0; k < adj.face_count(e); ++k) {
            const uint32_t f = adj.face(e, k);
            EXPECT_TRUE(f != 3 && f != 4 && f != 5) << f;
        }
    size_t non_manifold = 0;
    for (size_t e = 0; e < adj.edge_count(); ++e)
        if (adj.is_non_manifold(e)) {
            ++non_manifold;
            EXPECT_EQ(adj.edges[e], glm::uvec2(0, 1));
            EXPECT_EQ(adj.face_count(e), 4u);  // faces 0, 1, 2 and the zero-area face 6
            EXPECT_EQ(adj.faces[e], glm::uvec2(0, 1));
            EXPECT_EQ(adj.face(e, 2), 2u);
            EXPECT_EQ(adj.face(e, 3), 6u);
        }
    EXPECT_EQ(non_manifold, 1u);
    // Empty and vertex-only meshes.
    EXPECT_EQ(build_edge_adjacency(Mesh{}).edge_count(), 0u);
    Mesh points;
    points.positions = {{0, 0, 0}, {1, 1, 1}};
    const EdgeAdjacency none = build_edge_adjacency(points);
    EXPECT_EQ(none.edge_count(), 0u);
    EXPECT_TRUE(none.faces.empty() && none.more_faces.empty());
}

TEST(Adjacency, ClosedSphereHasNoBorderAndEulerCharacteristicTwo) {
    const Mesh m = builtin::sphere(16, 32, 1.0f);
    const EdgeAdjacency adj = build_edge_adjacency(m);
    expect_consistent(m, adj);
    for (size_t e = 0; e < adj.edge_count(); ++e) EXPECT_EQ(adj.face_count(e), 2u) << e;
    EXPECT_EQ(int64_t(m.vertex_count()) - int64_t(adj.edge_count()) + int64_t(m.triangle_count()), 2);
}

}  // namespace
}  // namespace inkshade::geometry
