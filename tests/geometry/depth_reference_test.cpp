// The answer key of exact_visibility_test.cpp checked against closed forms: depths of a plane
// and a sphere along pixel rays, window-to-view depth conversion, crack-free needles, and the
// checker's verdicts on paths placed by hand.
#include "geometry/depth_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>

#include "geometry/builtin_models.hpp"

namespace inkshade::test {
namespace {

constexpr int kWidth = 160, kHeight = 120;  // not square: the aspect must be handled

Camera camera_at(const glm::vec3& eye, bool orthographic) {
    Camera c;
    c.eye = eye;
    c.target = glm::vec3(0.0f);
    c.fov_degrees = 40.0f;
    c.orthographic = orthographic;
    c.ortho_height = 3.0f;
    c.near_plane = 1.0f;
    c.far_plane = 20.0f;
    return c;
}

// The world-space ray through image point p (pixels): from the near plane to the far plane.
std::pair<glm::dvec3, glm::dvec3> pixel_ray(const Camera& camera, glm::dvec2 p) {
    const glm::dmat4 m = glm::dmat4(camera.projection(float(kWidth) / float(kHeight))) * glm::dmat4(camera.view());
    const glm::dmat4 inv = glm::inverse(m);
    const auto at = [&](double z_ndc) {
        const glm::dvec4 w = inv * glm::dvec4(2.0 * p.x / kWidth - 1.0, 1.0 - 2.0 * p.y / kHeight, z_ndc, 1.0);
        return glm::dvec3(w) / w.w;
    };
    return {at(-1.0), at(1.0)};
}

Mesh plate(double tilt) {  // z = tilt · x over [−1, 1]², facing +z
    Mesh m;
    m.positions = {{-1, -1, -tilt}, {1, -1, tilt}, {1, 1, tilt}, {-1, 1, -tilt}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

void expect_plane_and_sphere_depths(bool orthographic) {
    const Camera camera = camera_at({0.8f, 0.6f, 5.0f}, orthographic);
    const glm::dvec3 eye(camera.eye), forward = glm::normalize(-eye);
    const int k = 4;

    const Mesh tilted = plate(0.3);
    const DepthReference plane(tilted, camera, kWidth, kHeight, k);
    EXPECT_EQ(plane.clipped_triangles(), 0u);
    const DepthReference sphere(builtin::sphere(128, 256, 1.0f), camera, kWidth, kHeight, k);
    size_t plane_pixels = 0, sphere_pixels = 0;
    for (int j = 0; j < kHeight * k; j += 7)
        for (int i = 0; i < kWidth * k; i += 7) {
            const auto [from, to] = pixel_ray(camera, {(i + 0.5) / k, (j + 0.5) / k});
            const glm::dvec3 d = to - from;
            // Plane z = 0.3 x: from.z + t d.z = 0.3 (from.x + t d.x).
            const double t = (0.3 * from.x - from.z) / (d.z - 0.3 * d.x);
            const glm::dvec3 hit = from + t * d;
            const double got = plane.depth(i, j);
            if (std::abs(hit.x) < 0.98 && std::abs(hit.y) < 0.98) {
                ++plane_pixels;
                EXPECT_NEAR(got, glm::dot(hit - eye, forward), 1e-5) << i << ", " << j;
            } else if (std::abs(hit.x) > 1.02 || std::abs(hit.y) > 1.02) {
                EXPECT_TRUE(std::isinf(got)) << i << ", " << j;
            }
            // Unit sphere: |from + s d| = 1, nearer root.
            const double a = glm::dot(d, d), b = 2.0 * glm::dot(from, d), c = glm::dot(from, from) - 1.0;
            const double disc = b * b - 4.0 * a * c;
            const double ref = sphere.depth(i, j);
            if (disc > a) {  // ray at least 30° from grazing: disc / a = 4 (1 − distance² from the centre)
                ++sphere_pixels;
                const double s = (-b - std::sqrt(disc)) / (2.0 * a);
                // The 128 x 256 sphere's faces lie up to 3e-4 inside the smooth one, / cos 60°.
                EXPECT_NEAR(ref, glm::dot(from + s * d - eye, forward), 1e-3) << i << ", " << j;
            } else if (disc < -0.05 * a) {
                EXPECT_TRUE(std::isinf(ref)) << i << ", " << j;
            }
        }
    EXPECT_GT(plane_pixels, 500u);
    EXPECT_GT(sphere_pixels, 300u);
}

TEST(DepthReference, PlaneAndSphereDepthsPerspective) { expect_plane_and_sphere_depths(false); }
TEST(DepthReference, PlaneAndSphereDepthsOrthographic) { expect_plane_and_sphere_depths(true); }

TEST(DepthReference, WindowDepthConvertsToViewDepth) {
    for (bool orthographic : {false, true}) {
        const Camera camera = camera_at({0.8f, 0.6f, 5.0f}, orthographic);
        const DepthReference reference(plate(0.0), camera, kWidth, kHeight);
        for (const glm::vec3 p : {glm::vec3(0.0f), glm::vec3(0.5f, -0.3f, 2.0f), glm::vec3(-1.0f, 1.0f, -8.0f)}) {
            const double window = reference.projection().project(p).z;
            // The window depth comes from the camera's float matrices: relative error ~1e-7.
            const double z = reference.projection().view_depth(p);
            EXPECT_NEAR(reference.view_depth_of_window(window), z, 1e-6 * z) << orthographic;
        }
    }
}

TEST(DepthReference, NeedleTrianglesLeaveNoCracks) {
    // A square of 2000 needles from one corner fan: every pixel centre inside is covered.
    Mesh fan;
    fan.positions.push_back({-1.0f, -1.0f, 0.0f});
    const int n = 1000;
    for (int s = 0; s <= n; ++s) fan.positions.push_back({1.0f, -1.0f + 2.0f * float(s) / n, 0.0f});
    for (int s = 0; s <= n; ++s) fan.positions.push_back({1.0f - 2.0f * float(s) / n, 1.0f, 0.0f});
    for (uint32_t s = 0; s < uint32_t(n); ++s) {
        fan.triangles.emplace_back(0u, 1 + s, 2 + s);
        fan.triangles.emplace_back(0u, uint32_t(n) + 2 + s, uint32_t(n) + 3 + s);
    }
    const Camera camera = camera_at({0.0f, 0.0f, 5.0f}, false);
    const DepthReference reference(fan, camera, kWidth, kHeight);
    const glm::dvec3 lo = reference.projection().project({-0.99f, 0.99f, 0.0f});
    const glm::dvec3 hi = reference.projection().project({0.99f, -0.99f, 0.0f});
    size_t inside = 0, holes = 0;
    for (int j = int(lo.y * 4); j < int(hi.y * 4); ++j)
        for (int i = int(lo.x * 4); i < int(hi.x * 4); ++i) {
            ++inside;
            holes += std::isinf(reference.depth(i, j));
        }
    EXPECT_GT(inside, 10000u);
    EXPECT_EQ(holes, 0u);
}

TEST(DepthReference, CheckerJudgesHandPlacedPaths) {
    // A line across the middle of a plate at z = 0, seen head-on: at the plate's depth it is
    // visible (right when visible, wrong when hidden); 0.01 behind it, it is hidden.
    const Camera camera = camera_at({0.0f, 0.0f, 5.0f}, false);
    const DepthReference reference(plate(0.0), camera, kWidth, kHeight);
    const auto path_at = [&](float z) {
        LinePath path;
        for (float x : {-0.5f, 0.0f, 0.5f}) {
            const glm::dvec3 q = reference.projection().project({x, 0.1f, z});
            path.points.emplace_back(float(q.x), float(q.y));
            path.depth.push_back(float(q.z));
        }
        return path;
    };
    const LinePath on = path_at(0.0f), behind = path_at(-0.01f);
    LinePath behind_hidden = behind;
    behind_hidden.level = 1;

    const VisibilityErrors visible_on = check_paths(reference, {on}, false);
    EXPECT_GT(visible_on.visible_length, 20.0);
    EXPECT_EQ(visible_on.wrongly_visible_length, 0.0) << visible_on;
    EXPECT_EQ(visible_on.level_mismatch_length, 0.0);

    const VisibilityErrors hidden_on = check_paths(reference, {on}, true);
    EXPECT_DOUBLE_EQ(hidden_on.wrongly_hidden_fraction(), 1.0) << hidden_on;
    EXPECT_DOUBLE_EQ(hidden_on.level_mismatch_length, hidden_on.hidden_length) << "hidden path of level 0";

    const VisibilityErrors visible_behind = check_paths(reference, {behind}, false);
    EXPECT_DOUBLE_EQ(visible_behind.wrongly_visible_fraction(), 1.0) << visible_behind;

    const VisibilityErrors hidden_behind = check_paths(reference, {behind_hidden}, true);
    EXPECT_EQ(hidden_behind.wrongly_hidden_length, 0.0) << hidden_behind;
    EXPECT_EQ(hidden_behind.level_mismatch_length, 0.0);
}

}  // namespace
}  // namespace inkshade::test
