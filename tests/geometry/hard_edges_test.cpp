#include "geometry/hard_edges.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>

#include "analytic_meshes.hpp"
#include "geometry/adjacency.hpp"
#include "geometry/normals.hpp"

namespace inkshade::geometry {
namespace {

const float kCos30 = std::cos(glm::radians(30.0f)) - 1e-6f;  // as auto_smooth compares

Mesh with_normals(Mesh m) {
    ensure_vertex_normals(m);
    return m;
}

// The hard bit of face f's edge between vertices v and w.
bool bit_of(const Mesh& m, const std::vector<uint8_t>& flags, uint32_t f, uint32_t v, uint32_t w) {
    const glm::uvec3 t = m.triangles[f];
    for (int k = 0; k < 3; ++k)
        if ((t[k] == v && t[(k + 1) % 3] == w) || (t[k] == w && t[(k + 1) % 3] == v)) return (flags[f] >> k) & 1u;
    ADD_FAILURE() << "edge not in face " << f;
    return false;
}

TEST(VertexFaces, ListsOnlyTheAskedStars) {
    const Mesh m = test::meshed_cube(4);
    const VertexFaces all = vertex_faces(m);
    std::vector<uint8_t> only(m.positions.size(), 0);
    for (size_t v = 0; v < only.size(); v += 3) only[v] = 1;
    const VertexFaces some = vertex_faces(m, only);
    ASSERT_EQ(some.offsets.size(), m.positions.size() + 1);
    for (uint32_t v = 0; v < m.positions.size(); ++v) {
        const std::vector<uint32_t> want =
            only[v] ? std::vector<uint32_t>(all.begin(v), all.end(v)) : std::vector<uint32_t>{};
        EXPECT_EQ(std::vector<uint32_t>(some.begin(v), some.end(v)), want) << v;
    }
}

// Every edge of a CAD part is decided as the edge table says: hard where three or more faces
// meet (a fin on the cube), where two flat sides meet at 90°, nowhere else, on both faces.
TEST(HardEdgeFlags, AgreeWithTheEdgeTable) {
    Mesh m = test::meshed_cube(6);
    // A fin standing on an interior edge of the +z side: that edge gets a third face.
    const EdgeAdjacency before = build_edge_adjacency(m);
    size_t inner = 0;
    while (!(m.positions[before.edges[inner].x].z > 0.99f && m.positions[before.edges[inner].y].z > 0.99f &&
             std::abs(m.positions[before.edges[inner].x].x) < 0.5f &&
             std::abs(m.positions[before.edges[inner].x].y) < 0.5f))
        ++inner;
    const glm::uvec2 e = before.edges[inner];
    m.positions.push_back(0.5f * (m.positions[e.x] + m.positions[e.y]) + glm::vec3(0.0f, 0.0f, 0.5f));
    m.triangles.push_back({e.x, e.y, uint32_t(m.positions.size() - 1)});
    m = with_normals(m);

    const std::vector<glm::vec3> fn = face_normals(m);
    const HardEdgeFlags hard = hard_edge_flags(m, fn, kCos30);
    const EdgeAdjacency adj = build_edge_adjacency(m);
    size_t hard_edges = 0, non_manifold = 0;
    for (size_t i = 0; i < adj.edge_count(); ++i) {
        const uint32_t count = adj.face_count(i);
        const bool want = count >= 3 || (count == 2 && glm::dot(fn[adj.face(i, 0)], fn[adj.face(i, 1)]) < kCos30);
        hard_edges += want;
        non_manifold += count >= 3;
        for (uint32_t k = 0; k < count; ++k)
            EXPECT_EQ(bit_of(m, hard.flags, adj.face(i, k), adj.edges[i].x, adj.edges[i].y), want) << i;
    }
    EXPECT_EQ(non_manifold, 1u);
    EXPECT_EQ(hard_edges, 12u * 6u + 1u);
}

// What the load builds grows with the hard edges, not the mesh: the star table lists only the
// stars near a possible hard edge, a band a few faces wide along the 12 n crease edges of a
// cube of 6 n² quads (4.25x from n = 32 to 128; a table of the whole mesh would grow 16x).
TEST(HardEdgeFlags, StarsGrowWithTheHardEdgesNotTheMesh) {
    size_t listed[2] = {0, 0};
    const int sizes[2] = {32, 128};
    for (int i = 0; i < 2; ++i) {
        const Mesh m = with_normals(test::meshed_cube(sizes[i]));
        const HardEdgeFlags hard = hard_edge_flags(m, face_normals(m), kCos30);
        listed[i] = hard.stars.faces.size();
        size_t bits = 0;
        for (uint8_t f : hard.flags) bits += std::popcount(unsigned(f));
        EXPECT_EQ(bits, 2u * 12u * size_t(sizes[i]));  // each crease edge, on both its faces
        if (i == 1) {
            EXPECT_LT(listed[i], 3 * m.triangles.size() / 8);  // under an eighth of the corners
        }
    }
    EXPECT_LT(listed[1], 5 * listed[0]);  // 4x the hard edges, 16x the faces
    EXPECT_GT(listed[1], 3 * listed[0]);
}

}  // namespace
}  // namespace inkshade::geometry
