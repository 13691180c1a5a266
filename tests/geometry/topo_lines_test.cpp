#include "geometry/topo_lines.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"
#include "geometry/feature_size.hpp"
#include "inkshade/error.hpp"

namespace inkshade::geometry {
namespace {

Camera perspective(const glm::vec3& eye) {
    Camera c;
    c.eye = eye;
    c.target = glm::vec3(0.0f);
    c.fov_degrees = 35.0f;
    return c;
}

// rtsc's default: 20 slices of constant depth across the bounding sphere. On the unit sphere
// each slice at height h along the view axis is a circle of radius sqrt(1 − h²).
TEST(TopoLines, SphereDepthSlicesAreCirclesAtTheirHeights) {
    const Mesh m = builtin::sphere(64, 128, 1.0f);
    const Camera camera = perspective({1.0f, 2.0f, 4.0f});
    const glm::dvec3 axis = glm::normalize(glm::dvec3(camera.eye));
    const BoundingSphere sphere = bounding_sphere(m);
    const std::vector<double> levels = topo_levels(m, camera, {});
    // Heights from the sphere's lowest point in steps of its diameter / 20.
    const double step = 2.0 * sphere.radius / 20.0, bottom = glm::dot(glm::dvec3(sphere.center), axis) - sphere.radius;
    ASSERT_GE(levels.size(), 20u);
    for (size_t k = 0; k < levels.size(); ++k) {
        const double steps = (levels[k] - bottom) / step;
        EXPECT_NEAR(steps, std::round(steps), 1e-5) << k;
        EXPECT_NEAR(levels[k] - levels[0], double(k) * step, 1e-6) << k;
    }
    EXPECT_GE(levels.front(), bottom - 1e-6);
    EXPECT_LE(levels.back(), bottom + 2.0 * sphere.radius + 1e-6);
    const auto segs = extract_topo_lines(m, m.normals, camera, {.back_faces = true});
    std::map<uint32_t, int> used;
    for (const LineSegment& s : segs) {
        const double h = levels.at(s.isoline);
        ++used[s.isoline];
        for (const glm::vec3& p : {s.a, s.b}) {
            EXPECT_NEAR(glm::dot(glm::dvec3(p), axis), h, 1e-5);  // linear: exactly on the plane
            const double radius = glm::length(glm::dvec3(p) - h * axis);
            EXPECT_NEAR(radius, std::sqrt(std::max(0.0, 1.0 - h * h)), 2e-3);
        }
    }
    // Every level strictly inside the sphere is one closed loop.
    size_t inside = 0;
    for (double h : levels) inside += std::abs(h) < 0.999;
    const auto loops = chain_segments(segs);
    EXPECT_EQ(loops.size(), inside);
    for (const Polyline& loop : loops) EXPECT_TRUE(loop.closed);
    // By default faces turned away are culled, as rtsc does: the eye at distance 4.6 sees the
    // sphere down to h = 1 / 4.6, so slices below h = 0.2 − a ring or two are gone.
    for (const LineSegment& s : extract_topo_lines(m, m.normals, camera))
        EXPECT_GT(levels.at(s.isoline), 0.217 - 0.08) << "on a face turned away";
    EXPECT_LT(extract_topo_lines(m, m.normals, camera).size(), segs.size() / 2);
}

// A map's contour lines of the torus around the z axis, z = (k + ½) · 0.1: at height h the
// torus is cut in two circles of radius R ± sqrt(r² − h²).
TEST(TopoLines, TorusWorldHeightsWithSpacingAndOffset) {
    const double R = 1.0, r = 0.4;
    const Mesh m = builtin::torus(float(R), float(r), 256, 128);
    const Camera camera = perspective({3.0f, 1.0f, 2.0f});
    const TopoOptions options{
        .direction = {0.0f, 0.0f, 2.0f}, .world = true, .spacing = 0.1f, .offset = 0.5f, .back_faces = true};
    // Every height (k + ½) · 0.1 inside the bounding sphere (radius about 1.4), of which those
    // with |h| < r cut the torus.
    const std::vector<double> levels = topo_levels(m, camera, options);
    ASSERT_GE(levels.size(), 28u);
    for (size_t k = 0; k < levels.size(); ++k) EXPECT_NEAR(levels[k], levels[0] + 0.1 * double(k), 1e-6);
    const double k0 = levels[0] / 0.1 - 0.5;
    EXPECT_NEAR(k0, std::round(k0), 1e-5);
    const auto segs = extract_topo_lines(m, m.normals, camera, options);
    ASSERT_FALSE(segs.empty());
    std::set<long> cut;
    for (const LineSegment& s : segs) {
        const double h = levels.at(s.isoline);
        cut.insert(std::lround(h * 100.0));
        for (const glm::vec3& p : {s.a, s.b}) {
            EXPECT_NEAR(p.z, h, 1e-6);
            const double d = std::hypot(double(p.x), double(p.y)), half = std::sqrt(r * r - h * h);
            EXPECT_NEAR(std::min(std::abs(d - (R - half)), std::abs(d - (R + half))), 0.0, 1e-3) << "h " << h;
        }
    }
    EXPECT_EQ(cut, (std::set<long>{-35, -25, -15, -5, 5, 15, 25, 35}));
    const auto loops = chain_segments(segs);
    EXPECT_EQ(loops.size(), 16u) << "two circles per level";
    for (const Polyline& loop : loops) EXPECT_TRUE(loop.closed);
}

TEST(TopoLines, OffsetShiftsAndSpacingIsChecked) {
    const Mesh m = builtin::sphere(16, 32, 1.0f);
    const Camera camera = perspective({0.0f, 0.0f, 4.0f});
    const auto plain = topo_levels(m, camera, {.count = 4});
    const auto shifted = topo_levels(m, camera, {.count = 4, .offset = 0.25f});
    ASSERT_FALSE(plain.empty());
    ASSERT_FALSE(shifted.empty());
    const double step = plain[1] - plain[0], shift = (shifted[0] - plain[0]) / step;
    EXPECT_NEAR(shift - std::floor(shift), 0.25, 1e-5);
    EXPECT_THROW(topo_levels(m, camera, {.spacing = 1e-6f}), InputError);
    EXPECT_THROW(topo_levels(m, camera, {.direction = glm::vec3(0.0f), .world = true}), InputError);
    EXPECT_THROW(topo_levels(m, camera, {.direction = glm::vec3(0.0f)}), InputError);
    EXPECT_TRUE(extract_topo_lines(Mesh{}, {}, camera).empty());
}

}  // namespace
}  // namespace inkshade::geometry
