// dash_paths: on/off lengths along a known circle and a straight line, odd patterns repeated
// as SVG does, attributes interpolated at the cuts.
#include "geometry/dash_pattern.hpp"

#include <gtest/gtest.h>

#include "geometry/stroke_paths.hpp"

namespace inkshade::geometry {
namespace {

using test::circle_path;
using test::path_length;
using test::straight_path;

TEST(DashPattern, OnAndOffLengthsAlongACircle) {
    // R = 50 sampled finely: the polygon's length is 2π 50 to 1e-4 relative.
    const LinePath circle = circle_path({100, 100}, 50, 3600);
    const double total = path_length(circle);
    const std::vector<LinePath> dashes = dash_paths({circle}, {10.0f, 5.0f});
    // Dashes start every 15 px from the loop's first point; the last may be cut short.
    ASSERT_EQ(dashes.size(), size_t(std::ceil(total / 15.0)));
    const double pi = 3.14159265358979323846;
    for (size_t k = 0; k < dashes.size(); ++k) {
        const LinePath& d = dashes[k];
        const double expected = std::min(10.0, total - 15.0 * double(k));
        EXPECT_NEAR(path_length(d), expected, 1e-3) << k;
        EXPECT_FALSE(d.closed);
        // Where a dash starts: at arc length 15 k, the angle 15 k / 50 from the first point.
        const double a = 15.0 * double(k) / 50.0;
        EXPECT_NEAR(d.points.front().x, 100.0 + 50.0 * std::cos(a), 2e-3) << k;
        EXPECT_NEAR(d.points.front().y, 100.0 - 50.0 * std::sin(a), 2e-3) << k;
        for (const glm::vec2& p : d.points) EXPECT_NEAR(glm::length(glm::dvec2(p) - glm::dvec2(100, 100)), 50.0, 1e-3);
    }
    (void)pi;
}

TEST(DashPattern, OddPatternsRepeatAndAttributesAreInterpolated) {
    LinePath line = straight_path({0, 0}, {100, 0}, 25.0f);
    line.width = {0.0f, 1.0f, 2.0f, 3.0f, 4.0f};                       // width = x / 25
    const std::vector<LinePath> dashes = dash_paths({line}, {20.0f});  // 20 on, 20 off
    ASSERT_EQ(dashes.size(), 3u);
    const float starts[3] = {0, 40, 80};
    for (int k = 0; k < 3; ++k) {
        EXPECT_FLOAT_EQ(dashes[k].points.front().x, starts[k]);
        EXPECT_FLOAT_EQ(dashes[k].points.back().x, starts[k] + 20.0f);
        EXPECT_NEAR(dashes[k].width.front(), starts[k] / 25.0f, 1e-5f);
        EXPECT_NEAR(dashes[k].width.back(), (starts[k] + 20.0f) / 25.0f, 1e-5f);
        EXPECT_EQ(dashes[k].width.size(), dashes[k].points.size());
    }
    // Solid patterns leave the paths as they are.
    EXPECT_EQ(dash_paths({line}, {0.0f}).at(0).points, line.points);
    EXPECT_EQ(dash_paths({line}, {}).at(0).points, line.points);
}

}  // namespace
}  // namespace inkshade::geometry
