#include "inkshade/mesh_stats.hpp"

#include <gtest/gtest.h>

namespace inkshade::geometry {
namespace {

// Indexed unit cube at `offset`, counter-clockwise seen from outside.
Mesh cube(glm::vec3 offset = glm::vec3(0.0f)) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (glm::vec3& p : m.positions) p += offset;
    m.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                   {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    return m;
}

void append(Mesh& to, const Mesh& from) {
    const auto base = uint32_t(to.positions.size());
    to.positions.insert(to.positions.end(), from.positions.begin(), from.positions.end());
    for (const glm::uvec3& t : from.triangles) to.triangles.push_back(t + base);
}

TEST(MeshStats, ClosedCubeIsSphereLike) {
    const MeshStats s = mesh_stats(cube());
    EXPECT_EQ(s.vertices, 8u);
    EXPECT_EQ(s.triangles, 12u);
    EXPECT_EQ(s.edges, 18u);
    EXPECT_EQ(s.boundary_edges, 0u);
    EXPECT_EQ(s.non_manifold_edges, 0u);
    EXPECT_EQ(s.degenerate_faces, 0u);
    EXPECT_EQ(s.duplicate_faces, 0u);
    EXPECT_EQ(s.components, 1u);
    EXPECT_EQ(s.unreferenced_vertices, 0u);
    EXPECT_EQ(s.euler_characteristic, 2);
}

TEST(MeshStats, SingleTriangleHasThreeBoundaryEdges) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}};
    const MeshStats s = mesh_stats(m);
    EXPECT_EQ(s.edges, 3u);
    EXPECT_EQ(s.boundary_edges, 3u);
    EXPECT_EQ(s.components, 1u);
    EXPECT_EQ(s.euler_characteristic, 1);
}

TEST(MeshStats, ThreeTrianglesOnOneEdgeAreNonManifold) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const MeshStats s = mesh_stats(m);
    EXPECT_EQ(s.non_manifold_edges, 1u);
    EXPECT_EQ(s.boundary_edges, 6u);
    EXPECT_EQ(s.edges, 7u);
}

TEST(MeshStats, DegenerateFacesAreCounted) {
    Mesh m = cube();
    m.triangles.push_back({0, 0, 1});  // repeated index
    m.positions.push_back({0.5f, 0, 0});
    m.triangles.push_back({0, 8, 1});  // collinear: zero area
    const MeshStats s = mesh_stats(m);
    EXPECT_EQ(s.degenerate_faces, 2u);
}

TEST(MeshStats, DuplicateFacesAreCountedOncePerRepeat) {
    Mesh m = cube();
    m.triangles.push_back({2, 1, 0});  // same set as {0, 2, 1}, any order
    m.triangles.push_back({1, 0, 2});
    m.triangles.push_back({4, 5, 6});
    const MeshStats s = mesh_stats(m);
    EXPECT_EQ(s.duplicate_faces, 3u);
    EXPECT_EQ(s.non_manifold_edges, 3u + 3u);  // the repeated faces' edges now have 3+ faces
}

TEST(MeshStats, TwoDisjointCubesAreTwoComponents) {
    Mesh m = cube();
    append(m, cube(glm::vec3(3, 0, 0)));
    const MeshStats s = mesh_stats(m);
    EXPECT_EQ(s.components, 2u);
    EXPECT_EQ(s.euler_characteristic, 4);
    EXPECT_EQ(s.boundary_edges, 0u);
}

TEST(MeshStats, UnreferencedVerticesAreExcludedFromEuler) {
    Mesh m = cube();
    m.positions.push_back({9, 9, 9});
    const MeshStats s = mesh_stats(m);
    EXPECT_EQ(s.unreferenced_vertices, 1u);
    EXPECT_EQ(s.components, 1u);
    EXPECT_EQ(s.euler_characteristic, 2);
}

TEST(MeshStats, EmptyMeshIsAllZero) {
    const MeshStats s = mesh_stats(Mesh{});
    EXPECT_EQ(s.vertices, 0u);
    EXPECT_EQ(s.edges, 0u);
    EXPECT_EQ(s.components, 0u);
    EXPECT_EQ(s.euler_characteristic, 0);
}

}  // namespace
}  // namespace inkshade::geometry
