// split_chains: strokes end at corners sharper than split-angle, at cusps where the image
// direction reverses, and every max-length pixels; the pieces share their cut points.
#include "geometry/chain_split.hpp"

#include <gtest/gtest.h>

#include "geometry/stroke_paths.hpp"

namespace inkshade::geometry {
namespace {

using test::circle_path;
using test::path_length;
using test::square_path;
using test::straight_path;

TEST(ChainSplit, SquareSplitsIntoFourStrokesAtItsCorners) {
    const LinePath square = square_path({10, 20}, 100);
    std::vector<LinePath> out = split_chains({square}, {.split_angle_degrees = 60.0f});
    ASSERT_EQ(out.size(), 4u);
    const glm::vec2 corners[4] = {{10, 20}, {110, 20}, {110, 120}, {10, 120}};
    for (int k = 0; k < 4; ++k) {
        const LinePath& s = out[k];
        EXPECT_FALSE(s.closed);
        EXPECT_NEAR(path_length(s), 100.0, 1e-3) << k;
        EXPECT_EQ(s.points.front(), corners[k]) << k;
        EXPECT_EQ(s.points.back(), corners[(k + 1) % 4]) << k;
        EXPECT_EQ(s.depth.size(), s.points.size());
        EXPECT_EQ(s.strength.size(), s.points.size());
    }
    // 90° turns are not sharper than 100°: the loop stays whole.
    out = split_chains({square}, {.split_angle_degrees = 100.0f});
    ASSERT_EQ(out.size(), 1u);
    EXPECT_TRUE(out[0].closed);
    EXPECT_EQ(out[0].points, square.points);
    // A circle of 360 points turns 1° a vertex.
    EXPECT_EQ(split_chains({circle_path({100, 100}, 50, 360)}, {.split_angle_degrees = 2.0f}).size(), 1u);
    EXPECT_EQ(split_chains({circle_path({100, 100}, 50, 360)}, {.split_angle_degrees = 0.5f}).size(), 360u);
}

TEST(ChainSplit, CuspSplitsWhereTheDirectionReverses) {
    // The semicubical parabola (x, y) = 60 (t², t³), t in [-1, 1]: the cusp of a projected
    // contour, at the origin (moved to (50, 100)).
    LinePath cusp;
    for (int i = -200; i <= 200; ++i) {
        const float t = i / 200.0f;
        cusp.points.emplace_back(50.0f + 60.0f * t * t, 100.0f + 60.0f * t * t * t);
    }
    const std::vector<LinePath> out = split_chains({cusp}, {.cusps = true});
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].points.back(), glm::vec2(50, 100));
    EXPECT_EQ(out[1].points.front(), glm::vec2(50, 100));
    EXPECT_EQ(out[0].points.size() + out[1].points.size(), cusp.points.size() + 1);
    // Corners of 90° and smooth curves are no cusps.
    EXPECT_EQ(split_chains({square_path({0, 0}, 50)}, {.cusps = true}).size(), 1u);
    EXPECT_EQ(split_chains({circle_path({100, 100}, 3, 24)}, {.cusps = true}).size(), 1u);
    // Without the option nothing splits.
    EXPECT_EQ(split_chains({cusp}, {}).size(), 1u);
}

TEST(ChainSplit, MaxLengthCutsEqualPiecesWithInterpolatedAttributes) {
    LinePath line = straight_path({0, 10}, {250, 10}, 10.0f);
    for (size_t i = 0; i < line.points.size(); ++i) line.depth[i] = line.points[i].x / 250.0f;
    const std::vector<LinePath> out = split_chains({line}, {.max_length_px = 100.0f});
    ASSERT_EQ(out.size(), 3u);  // 250 / 100 → 3 pieces of 83.3
    for (size_t k = 0; k < 3; ++k) {
        EXPECT_NEAR(path_length(out[k]), 250.0 / 3.0, 1e-3);
        EXPECT_NEAR(out[k].points.front().x, 250.0 * k / 3.0, 1e-3);
        // Depth interpolated at the cut: still x / 250.
        EXPECT_NEAR(out[k].depth.front(), out[k].points.front().x / 250.0f, 1e-6);
        EXPECT_NEAR(out[k].depth.back(), out[k].points.back().x / 250.0f, 1e-6);
    }
    // A loop is cut too: a circle of circumference 2π 50 ≈ 314 into 4 pieces under 100.
    const std::vector<LinePath> loop = split_chains({circle_path({100, 100}, 50, 720)}, {.max_length_px = 100.0f});
    ASSERT_EQ(loop.size(), 4u);
    for (const LinePath& p : loop) EXPECT_NEAR(path_length(p), 2.0 * 3.14159265 * 50 / 4, 0.05);
}

}  // namespace
}  // namespace inkshade::geometry
