// stroke_widths: each thickness modifier on a path with an exact answer (taper along a
// straight line, curvature and calligraphy on circles, depth on a known range, occlusion
// level), the seeded noise's bounds and determinism, and the depth range's inverse of the
// GL projection.
#include "geometry/stroke_thickness.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/stroke_noise.hpp"
#include "geometry/stroke_paths.hpp"

namespace inkshade::geometry {
namespace {

using test::circle_path;
using test::straight_path;

constexpr double kPi = 3.14159265358979323846;

TEST(StrokeThickness, TaperInAndOutAreZeroAtTheEndsAndFullBetween) {
    const LinePath line = straight_path({10, 50}, {210, 50});  // 200 px, a point a pixel
    StrokeThickness t{.width = 4.0f, .taper_in_px = 50.0f, .taper_out_px = 25.0f};
    const std::vector<float> w = stroke_widths(line, t, {}, 0);
    ASSERT_EQ(w.size(), 201u);
    EXPECT_FLOAT_EQ(w[0], 0.0f);
    EXPECT_FLOAT_EQ(w[25], 2.0f);  // half way through the taper in
    EXPECT_FLOAT_EQ(w[50], 4.0f);
    EXPECT_FLOAT_EQ(w[100], 4.0f);
    EXPECT_FLOAT_EQ(w[175], 4.0f);
    EXPECT_FLOAT_EQ(w[190], 4.0f * 10.0f / 25.0f);
    EXPECT_FLOAT_EQ(w[200], 0.0f);
    // A loop has no ends.
    for (float v : stroke_widths(circle_path({100, 100}, 40, 200), t, {}, 0)) EXPECT_FLOAT_EQ(v, 4.0f);
    EXPECT_TRUE(t.varies());
    EXPECT_FALSE(StrokeThickness{.width = 4.0f}.varies());
}

TEST(StrokeThickness, ImageCurvatureOfACircleIsOneOverItsRadius) {
    for (float r : {5.0f, 20.0f, 200.0f}) {
        const LinePath c = circle_path({300, 300}, r, 2000);
        for (float k : image_curvature(c)) EXPECT_NEAR(k, 1.0f / r, 1e-2f / r) << r;  // float points: 1 %
    }
    for (float k : image_curvature(straight_path({0, 0}, {100, 30}))) EXPECT_NEAR(k, 0.0f, 1e-5f);
}

TEST(StrokeThickness, CurvatureWidthBlendsBetweenItsFactors) {
    StrokeThickness t{.width = 2.0f, .curvature_factors = {1.0f, 3.0f}, .curvature_radius_px = 10.0f};
    // Radius 20: κ × 10 = 0.5, half way from 1 to 3.
    for (float w : stroke_widths(circle_path({100, 100}, 20, 400), t, {}, 0)) EXPECT_NEAR(w, 4.0f, 0.01f);
    // Radius 5: past 1 / curvature-radius, the second factor.
    for (float w : stroke_widths(circle_path({100, 100}, 5, 200), t, {}, 0)) EXPECT_NEAR(w, 6.0f, 1e-4f);
    for (float w : stroke_widths(straight_path({0, 0}, {80, 0}), t, {}, 0)) EXPECT_NEAR(w, 2.0f, 1e-5f);
}

TEST(StrokeThickness, CalligraphicWidthFollowsTheNib) {
    // Nib horizontal: the circle's top and bottom (moving horizontally) are full width, its
    // left and right (moving vertically) 1 - calligraphy; between, 1 - c (1 - |cos|).
    const LinePath c = circle_path({100, 100}, 40, 720);
    StrokeThickness t{.width = 4.0f, .calligraphy = 0.75f, .nib_angle_degrees = 0.0f};
    const std::vector<float> w = stroke_widths(c, t, {}, 0);
    EXPECT_NEAR(w[0], 1.0f, 1e-3f);    // angle 0: the right side, moving up
    EXPECT_NEAR(w[180], 4.0f, 1e-3f);  // angle 90°: the top, moving left
    EXPECT_NEAR(w[360], 1.0f, 1e-3f);
    EXPECT_NEAR(w[540], 4.0f, 1e-3f);
    // At angle 60° the direction is 150°: |cos(150°)| = 0.866.
    EXPECT_NEAR(w[120], 4.0f * (1.0f - 0.75f * (1.0f - 0.8660254f)), 1e-3f);
    // Nib vertical: the other way round.
    t.nib_angle_degrees = 90.0f;
    const std::vector<float> v = stroke_widths(c, t, {}, 0);
    EXPECT_NEAR(v[0], 4.0f, 1e-3f);
    EXPECT_NEAR(v[180], 1.0f, 1e-3f);
}

TEST(StrokeThickness, DepthWidthIsLinearOverTheModelsDepthRange) {
    // Orthographic window depth is linear: near 0 + d × 10; the model spans view depths 2..6.
    const ViewDepthRange range{
        .orthographic = true, .near_plane = 0.0f, .far_plane = 10.0f, .nearest = 2.0, .farthest = 6.0};
    LinePath line = straight_path({0, 0}, {4, 0});
    line.depth = {0.1f, 0.2f, 0.4f, 0.6f, 0.9f};  // view depths 1, 2, 4, 6, 9
    const StrokeThickness t{.width = 2.0f, .depth_factors = {2.0f, 0.5f}};
    const std::vector<float> w = stroke_widths(line, t, range, 0);
    EXPECT_NEAR(w[0], 4.0f, 1e-5f);  // nearer than the model: clamped to the near factor
    EXPECT_NEAR(w[1], 4.0f, 1e-5f);
    EXPECT_NEAR(w[2], 2.5f, 1e-5f);  // half way: 2 × (2 + 0.5) / 2
    EXPECT_NEAR(w[3], 1.0f, 1e-5f);
    EXPECT_NEAR(w[4], 1.0f, 1e-5f);
}

TEST(StrokeThickness, ViewDepthRangeUndoesThePerspectiveWindowDepth) {
    Camera cam;
    cam.eye = {0, 0, 10};
    cam.target = {0, 0, 0};
    cam.near_plane = 0.5f;
    cam.far_plane = 40.0f;
    const glm::mat4 clip = cam.projection(1.0f) * cam.view();
    const ViewDepthRange range = ViewDepthRange::of_sphere(cam, glm::vec3(0.0f), 3.0f);
    EXPECT_DOUBLE_EQ(range.nearest, 7.0);
    EXPECT_DOUBLE_EQ(range.farthest, 13.0);
    for (float z : {-3.0f, -1.0f, 0.0f, 2.5f}) {
        const glm::vec4 c = clip * glm::vec4(0.3f, -0.2f, z, 1.0f);
        const float window = 0.5f * (c.z / c.w + 1.0f);
        EXPECT_NEAR(range.view_depth(window), 10.0 - z, 2e-4) << z;
        EXPECT_NEAR(range.fraction(window), (3.0 - z) / 6.0, 1e-4) << z;
    }
}

TEST(StrokeThickness, LevelAndStrengthScaleTheWidth) {
    LinePath line = straight_path({0, 0}, {2, 0});
    line.level = 2;
    line.strength = {0.0f, 0.5f, 1.0f};
    const std::vector<float> w =
        stroke_widths(line, {.width = 4.0f, .strength_scales = true, .level_factor = 0.5f}, {}, 0);
    EXPECT_FLOAT_EQ(w[0], 0.0f);
    EXPECT_FLOAT_EQ(w[1], 0.5f);  // 4 × 0.25 × 0.5
    EXPECT_FLOAT_EQ(w[2], 1.0f);
}

TEST(StrokeThickness, NoiseIsSeededBoundedAndSmooth) {
    const LinePath line = straight_path({0, 0}, {1000, 0});
    const StrokeThickness t{.width = 4.0f, .noise = 0.5f, .noise_period_px = 40.0f, .seed = 7};
    const std::vector<float> a = stroke_widths(line, t, {}, 3);
    EXPECT_EQ(a, stroke_widths(line, t, {}, 3)) << "deterministic for a seed";
    StrokeThickness other = t;
    other.seed = 8;
    EXPECT_NE(a, stroke_widths(line, other, {}, 3)) << "another seed, other widths";
    EXPECT_NE(a, stroke_widths(line, t, {}, 4)) << "another path, other widths";
    float lo = 1e9f, hi = -1e9f, step = 0.0f;
    for (size_t i = 0; i < a.size(); ++i) {
        lo = std::min(lo, a[i]);
        hi = std::max(hi, a[i]);
        if (i > 0) step = std::max(step, std::abs(a[i] - a[i - 1]));
    }
    EXPECT_GE(lo, 2.0f);  // 4 × (1 - 0.5)
    EXPECT_LE(hi, 6.0f);
    EXPECT_LT(lo, 3.0f) << "the noise uses its range";
    EXPECT_GT(hi, 5.0f);
    // Smooth: the quintic fade's slope is at most 15/8 of a lattice difference (at most 2) per
    // period, so a pixel changes the width by at most 4 × 0.5 × 2 × 15/8 / 40.
    EXPECT_LE(step, 4.0f * 0.5f * 2.0f * 15.0f / 8.0f / 40.0f + 1e-4f);
    // The lattice values themselves stay in [-1, 1] for any seed and stream.
    for (uint32_t seed = 0; seed < 50; ++seed)
        for (double x = -5.0; x < 5.0; x += 0.37) {
            const float v = value_noise(seed, noise_stream(seed, 1), x);
            EXPECT_GE(v, -1.0f);
            EXPECT_LE(v, 1.0f);
        }
}

}  // namespace
}  // namespace inkshade::geometry
