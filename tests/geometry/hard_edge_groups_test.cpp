#include "geometry/hard_edge_groups.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>

#include "analytic_meshes.hpp"
#include "geometry/auto_smooth.hpp"
#include "geometry/builtin_models.hpp"
#include "geometry/hard_edge_contours.hpp"
#include "geometry/hard_edges.hpp"
#include "geometry/normals.hpp"

namespace inkshade::geometry {
namespace {

// A 40 x 40 grid over the unit square: edges 0.025 long, a tenth of the diagonal 0.141.
struct Grid {
    static constexpr int kCells = 40;
    Mesh mesh;
    std::vector<uint8_t> flags;
    Grid() {
        for (int j = 0; j <= kCells; ++j)
            for (int i = 0; i <= kCells; ++i) mesh.positions.push_back({float(i) / kCells, float(j) / kCells, 0.0f});
        test::add_grid_triangles(mesh, kCells, kCells);
        flags.assign(mesh.triangles.size(), 0);
    }
    static uint32_t v(int i, int j) { return uint32_t(j * (kCells + 1) + i); }
    // Sets or reads the bits of edge (a, b) in every face that has it.
    void flag(uint32_t a, uint32_t b) { each(a, b, [&](size_t f, int k) { flags[f] |= uint8_t(1u << k); }); }
    bool hard(uint32_t a, uint32_t b) const {
        bool any = false;
        each(a, b, [&](size_t f, int k) { any = any || (flags[f] >> k & 1); });
        return any;
    }
    void each(uint32_t a, uint32_t b, const auto& fn) const {
        for (size_t f = 0; f < mesh.triangles.size(); ++f)
            for (int k = 0; k < 3; ++k) {
                const uint32_t p = mesh.triangles[f][k], q = mesh.triangles[f][(k + 1) % 3];
                if ((p == a && q == b) || (p == b && q == a)) fn(f, k);
            }
    }
    // The ring of edges around the square block of `n` x `n` cells from (i, j).
    std::vector<std::pair<uint32_t, uint32_t>> ring(int i, int j, int n) const {
        std::vector<std::pair<uint32_t, uint32_t>> out;
        for (int s = 0; s < n; ++s) {
            out.emplace_back(v(i + s, j), v(i + s + 1, j));
            out.emplace_back(v(i + s, j + n), v(i + s + 1, j + n));
            out.emplace_back(v(i, j + s), v(i, j + s + 1));
            out.emplace_back(v(i + n, j + s), v(i + n, j + s + 1));
        }
        return out;
    }
};

TEST(HardEdgeGroups, SmallCompactGroupsAreDroppedLongOrWideOnesKept) {
    Grid g;
    // A sliver triangle's three edges (a fold of a decimated scan).
    const std::vector<std::pair<uint32_t, uint32_t>> triangle = {
        {Grid::v(5, 5), Grid::v(6, 5)}, {Grid::v(6, 5), Grid::v(6, 6)}, {Grid::v(5, 5), Grid::v(6, 6)}};
    using Edges = std::vector<std::pair<uint32_t, uint32_t>>;
    const Edges small_ring = g.ring(20, 5, 2);   // 8 edges, 0.07 across
    const Edges large_ring = g.ring(20, 20, 3);  // 12 edges, 0.106 across: kept by its count
    std::vector<std::pair<uint32_t, uint32_t>> line;  // 6 edges, 0.15 long: kept by its extent
    for (int j = 2; j < 8; ++j) line.emplace_back(Grid::v(35, j), Grid::v(35, j + 1));
    for (const Edges* group : std::initializer_list<const Edges*>{&triangle, &small_ring, &large_ring, &line})
        for (const auto& [a, b] : *group) g.flag(a, b);
    drop_small_hard_edge_groups(g.mesh, g.flags);
    for (const auto& [a, b] : triangle) EXPECT_FALSE(g.hard(a, b));
    for (const auto& [a, b] : small_ring) EXPECT_FALSE(g.hard(a, b));
    for (const auto& [a, b] : large_ring) EXPECT_TRUE(g.hard(a, b));
    for (const auto& [a, b] : line) EXPECT_TRUE(g.hard(a, b));
    // Nothing else was set on the way.
    size_t bits = 0;
    for (uint8_t f : g.flags) bits += size_t(std::popcount(f));
    EXPECT_EQ(bits, 2u * (large_ring.size() + line.size()));  // each edge has two faces
}

// A small solid's edges span the model: a regular tetrahedron keeps its six (70.5° apart).
TEST(HardEdgeGroups, TetrahedronKeepsItsSixEdges) {
    Mesh m;
    m.positions = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    m.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    ensure_vertex_normals(m);
    auto_smooth(m, 30.0f);
    ASSERT_TRUE(m.has_hard_edges());
    EXPECT_EQ(hard_edge_table(m).edges.size(), 6u);
}

}  // namespace
}  // namespace inkshade::geometry
