#include "geometry/duplicate_faces.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>

#include "inkshade/mesh_stats.hpp"

namespace inkshade::geometry {
namespace {

Mesh quad_mesh() {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

TEST(DuplicateFaces, SameAndOppositeWindingAndEveryRotationAreDuplicates) {
    const std::vector<glm::uvec3> t = {{0, 1, 2}, {1, 2, 0}, {2, 1, 0}, {0, 2, 3}, {0, 2, 1}, {3, 2, 0}, {0, 1, 3}};
    const std::vector<uint8_t> expected = {0, 1, 1, 0, 1, 1, 0};
    EXPECT_EQ(find_duplicate_faces(t), expected);
}

TEST(DuplicateFaces, RepeatedIndicesCompareAsMultisets) {
    // {0,0,1} and {1,0,0} are the same face; {0,1,1} is not.
    const std::vector<glm::uvec3> t = {{0, 0, 1}, {0, 1, 1}, {1, 0, 0}, {5, 5, 5}, {5, 5, 5}};
    const std::vector<uint8_t> expected = {0, 0, 1, 0, 1};
    EXPECT_EQ(find_duplicate_faces(t), expected);
}

TEST(DuplicateFaces, EmptyAndSingleFace) {
    EXPECT_TRUE(find_duplicate_faces({}).empty());
    EXPECT_EQ(find_duplicate_faces({{0, 1, 2}}), std::vector<uint8_t>{0});
}

TEST(DuplicateFaces, DropKeepsFirstOccurrencesInOrderWithTheirMaterials) {
    Mesh m = quad_mesh();
    m.triangles = {{0, 1, 2}, {2, 1, 0}, {0, 2, 3}, {1, 2, 0}, {3, 2, 0}, {0, 1, 3}};
    m.materials.resize(6);
    m.face_materials = {0, 1, 2, 3, 4, 5};
    EXPECT_EQ(drop_duplicate_faces(m), 3u);
    const std::vector<glm::uvec3> triangles = {{0, 1, 2}, {0, 2, 3}, {0, 1, 3}};
    EXPECT_EQ(m.triangles, triangles);
    EXPECT_EQ(m.face_materials, (std::vector<uint32_t>{0, 2, 5}));
    EXPECT_EQ(m.positions.size(), 4u);  // vertices are left alone
}

TEST(DuplicateFaces, FaceAndItsReverseKeepOneFace) {
    Mesh m = quad_mesh();
    m.triangles = {{0, 1, 2}, {0, 2, 1}};
    EXPECT_EQ(drop_duplicate_faces(m), 1u);
    ASSERT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
}

TEST(DuplicateFaces, NoDuplicatesLeavesTheMeshAsItWas) {
    Mesh m = quad_mesh();
    m.face_materials = {0, 0};
    m.materials.resize(1);
    const Mesh before = m;
    EXPECT_EQ(drop_duplicate_faces(m), 0u);
    EXPECT_EQ(m.triangles, before.triangles);
    EXPECT_EQ(m.face_materials, before.face_materials);
}

TEST(DuplicateFaces, MaterialsOfAnotherLengthAreLeftAlone) {
    Mesh m = quad_mesh();
    m.triangles.push_back({2, 0, 1});
    EXPECT_EQ(drop_duplicate_faces(m), 1u);
    EXPECT_TRUE(m.face_materials.empty());
}

// Many faces over few vertices (so many repeats, in runs that the parallel sort spreads across
// blocks) against a plain std::set of sorted triples.
TEST(DuplicateFaces, AgreesWithASetOfSortedTriples) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<uint32_t> vertex(0, 40);
    std::vector<glm::uvec3> t(300000);
    for (glm::uvec3& f : t) f = {vertex(rng), vertex(rng), vertex(rng)};
    std::set<std::array<uint32_t, 3>> seen;
    std::vector<uint8_t> expected;
    for (const glm::uvec3& f : t) {
        std::array<uint32_t, 3> k{f.x, f.y, f.z};
        std::sort(k.begin(), k.end());
        expected.push_back(seen.insert(k).second ? 0 : 1);
    }
    EXPECT_EQ(find_duplicate_faces(t), expected);

    Mesh m;
    m.positions.resize(41);
    m.triangles = t;
    EXPECT_EQ(drop_duplicate_faces(m), t.size() - seen.size());
    EXPECT_EQ(m.triangles.size(), seen.size());
    EXPECT_EQ(find_duplicate_faces(m.triangles), std::vector<uint8_t>(seen.size(), 0));
}

TEST(DuplicateFaces, MeshStatsCountsTheSameFaces) {
    Mesh m = quad_mesh();
    m.triangles = {{0, 1, 2}, {2, 1, 0}, {0, 2, 3}, {1, 2, 0}, {9, 9, 9}, {9, 9, 9}};  // last two out of range
    EXPECT_EQ(mesh_stats(m).duplicate_faces, 2u);
}

}  // namespace
}  // namespace inkshade::geometry
