// sketch_passes: n displaced copies of each stroke, the same for a seed and others for another,
// every point within the jitter of its original.
#include "geometry/sketch_passes.hpp"

#include <gtest/gtest.h>

#include "geometry/stroke_paths.hpp"

namespace inkshade::geometry {
namespace {

TEST(SketchPasses, DeterministicForASeedAndBoundedByTheJitter) {
    const LinePath circle = test::circle_path({200, 200}, 80, 500);
    const LinePath line = test::straight_path({10, 10}, {390, 30});
    const SketchOptions o{.passes = 3, .jitter_px = 2.5f, .period_px = 40.0f, .seed = 11};
    const std::vector<LinePath> a = sketch_passes({circle, line}, o);
    ASSERT_EQ(a.size(), 6u);
    const std::vector<LinePath> again = sketch_passes({circle, line}, o);
    for (size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k].points, again[k].points) << k;
    SketchOptions other = o;
    other.seed = 12;
    const std::vector<LinePath> b = sketch_passes({circle, line}, other);
    for (size_t k = 0; k < a.size(); ++k) EXPECT_NE(a[k].points, b[k].points) << k;
    // Each copy of a path differs from the other copies, and keeps its attributes.
    EXPECT_NE(a[0].points, a[1].points);
    EXPECT_NE(a[1].points, a[2].points);
    EXPECT_TRUE(a[0].closed);
    EXPECT_EQ(a[3].depth, line.depth);
    double worst = 0.0, sum = 0.0;
    size_t count = 0;
    for (size_t k = 0; k < a.size(); ++k) {
        const LinePath& original = k < 3 ? circle : line;
        ASSERT_EQ(a[k].points.size(), original.points.size());
        for (size_t i = 0; i < original.points.size(); ++i) {
            const double d = glm::length(glm::dvec2(a[k].points[i] - original.points[i]));
            worst = std::max(worst, d);
            sum += d;
            ++count;
        }
    }
    EXPECT_LE(worst, 2.5 + 1e-4);
    EXPECT_GT(worst, 1.5) << "the jitter is used";
    EXPECT_GT(sum / count, 0.5);
    // One pass without jitter: unchanged.
    const std::vector<LinePath> same = sketch_passes({circle}, {});
    ASSERT_EQ(same.size(), 1u);
    EXPECT_EQ(same[0].points, circle.points);
}

}  // namespace
}  // namespace inkshade::geometry
