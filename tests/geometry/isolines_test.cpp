#include "geometry/isolines.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "geometry/analytic_meshes.hpp"
#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"

namespace inkshade::geometry {
namespace {

// f = y (the pole axis) on a coarse unit sphere, levels 0.1 and 0.12: the two circles are
// 1.2° apart inside one ring of quads, 22.5° high, so they cross the same 32 edges (16 along
// meridians, 16 diagonals).
TEST(Isolines, LevelsCrossingTheSameEdgesChainApart) {
    const Mesh m = builtin::sphere(8, 16, 1.0f);
    std::vector<float> y;
    for (const glm::vec3& p : m.positions) y.push_back(p.y);
    const std::vector<double> levels = {0.10, 0.12};
    const auto segs = extract_isolines(m, y, levels);
    std::map<uint64_t, std::set<uint32_t>> isolines_on_edge;
    for (const LineSegment& s : segs) {
        ASSERT_LT(s.isoline, 2u);
        isolines_on_edge[s.edge_a].insert(s.isoline);
        isolines_on_edge[s.edge_b].insert(s.isoline);
    }
    size_t shared = 0;
    for (const auto& [key, set] : isolines_on_edge) shared += set.size() == 2;
    EXPECT_EQ(shared, 32u) << "the scene must put both levels on the same edges";

    const auto lines = chain_segments(segs);
    ASSERT_EQ(lines.size(), 2u) << "one closed loop per level";
    std::set<int> levels_seen;
    for (const Polyline& line : lines) {
        EXPECT_TRUE(line.closed);
        EXPECT_EQ(line.points.size(), 32u);  // one point per edge crossed
        const double level = std::abs(line.points[0].y - 0.10) < 0.005 ? 0.10 : 0.12;
        levels_seen.insert(int(std::lround(level * 100.0)));
        for (const glm::vec3& p : line.points) EXPECT_NEAR(p.y, level, 1e-6) << "every point on one level";
    }
    EXPECT_EQ(levels_seen, (std::set<int>{10, 12}));
}

// f linear in position: linear interpolation along an edge is exact, so every point lies on its
// level to float rounding; every segment has the higher values on its left.
TEST(Isolines, PointsOfALinearFunctionLieOnTheLevelHigherSideLeft) {
    Mesh m;
    const int nx = 20, ny = 10;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) m.positions.emplace_back(0.1f * float(i), 0.1f * float(j) + 0.013f * i, 0.0f);
    test::add_grid_triangles(m, nx, ny);
    std::vector<float> f;
    for (const glm::vec3& p : m.positions) f.push_back(p.x + 0.5f * p.y);
    const std::vector<double> levels = {0.3, 0.7, 1.05, 1.5};
    const auto segs = extract_isolines(m, f, levels);
    ASSERT_GT(segs.size(), 40u);
    std::map<uint32_t, int> per_level;
    for (const LineSegment& s : segs) {
        const double level = levels.at(s.isoline);
        ++per_level[s.isoline];
        for (const glm::vec3& p : {s.a, s.b}) EXPECT_NEAR(p.x + 0.5 * p.y, level, 2e-6);
        // The gradient (1, 0.5) points to the left of a → b (faces counter-clockwise from +z).
        const glm::vec2 d(s.b - s.a);
        EXPECT_GT(-d.y * 1.0f + d.x * 0.5f, 0.0f) << "isoline " << s.isoline;
        EXPECT_EQ(s.strength_a, 1.0f);
        EXPECT_EQ(s.strength_b, 1.0f);
    }
    EXPECT_EQ(per_level.size(), levels.size());
    for (const Polyline& line : chain_segments(segs)) EXPECT_FALSE(line.closed);
    EXPECT_EQ(chain_segments(segs).size(), levels.size()) << "one open line across the grid per level";
}

// A vertex exactly on a level counts as above it: a level through a corner gives one segment
// (from the corner to the opposite edge), and several levels in one face one each.
TEST(Isolines, SeveralLevelsInOneFaceAndLevelsThroughVertices) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}};
    const std::vector<float> f = {0.0f, 1.0f, 2.0f};
    const auto segs = extract_isolines(m, f, {0.5, 1.0, 1.5, 2.0, 2.5});
    // 2.0 touches the face at vertex 2 only: a segment of no length there (as extract_contours
    // gives where g = 0 at a vertex), which chains with its neighbours'; 2.5 misses the face.
    ASSERT_EQ(segs.size(), 4u);
    EXPECT_EQ(segs[3].a, glm::vec3(0, 1, 0));
    EXPECT_EQ(segs[3].b, glm::vec3(0, 1, 0));
    for (size_t k = 0; k < segs.size(); ++k) EXPECT_EQ(segs[k].isoline, uint32_t(k));
    // Level 1: from vertex 1 (on edge 0-1, t = 1) to the middle of edge 0-2.
    const LineSegment& one = segs[1];
    const bool a_at_vertex = one.a == glm::vec3(1, 0, 0);
    EXPECT_TRUE(a_at_vertex || one.b == glm::vec3(1, 0, 0));
    EXPECT_EQ(a_at_vertex ? one.b : one.a, glm::vec3(0, 0.5f, 0));
}

TEST(Isolines, BadInputGivesNoSegmentsOrThrows) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    m.triangles = {{0, 1, 2}, {1, 3, 2}, {0, 0, 1}, {0, 1, 7}};
    EXPECT_THROW(extract_isolines(m, {0.0f, 1.0f}, {0.5}), std::invalid_argument);
    const std::vector<float> f = {0.0f, 1.0f, std::nanf(""), 1.0f};
    const auto segs = extract_isolines(m, f, {0.5});
    EXPECT_TRUE(segs.empty()) << "face 0 and 1 touch the NaN vertex, 2 repeats an index, 3 is out of range";
    EXPECT_TRUE(extract_isolines(m, {0.0f, 1.0f, 0.0f, 1.0f}, {}).empty());
}

}  // namespace
}  // namespace inkshade::geometry
