#include "geometry/isophotes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"
#include "geometry/isolines.hpp"
#include "inkshade/error.hpp"

namespace inkshade::geometry {
namespace {

Camera perspective(const glm::vec3& eye, const glm::vec3& up = {0, 1, 0}) {
    Camera c;
    c.eye = eye;
    c.target = glm::vec3(0.0f);
    c.up = up;
    c.fov_degrees = 35.0f;
    return c;
}

// The camera's axes in world coordinates, built here from eye, target and up (not from
// Camera::view) to check the light's turning independently.
glm::dvec3 camera_axis_in_world(const Camera& c, const glm::dvec3& d) {
    const glm::dvec3 back = glm::normalize(glm::dvec3(c.eye - c.target));
    const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(c.up), back));
    const glm::dvec3 up = glm::cross(back, right);
    return glm::normalize(d.x * right + d.y * up + d.z * back);
}

// On the unit sphere n = p, so the isophote n·l = c is the circle at angle acos(c) from l.
// The light comes from the upper right behind the viewer's shoulder, so both lit and unlit
// levels face the camera; with the back faces every level's circle is one closed loop.
TEST(Isophotes, SphereIsophotesAreCirclesAtTheirAngleFromTheLight) {
    const Mesh m = builtin::sphere(64, 128, 1.0f);
    const Camera camera = perspective({1.0f, 1.5f, 4.0f});
    const IsophoteOptions options{.direction = {1.0f, 1.0f, 1.0f}, .levels = 5, .back_faces = true};
    const glm::dvec3 l = camera_axis_in_world(camera, {1.0, 1.0, 1.0});
    const std::vector<double> levels = isophote_levels(options);
    ASSERT_EQ(levels, (std::vector<double>{-0.8, -0.6, -0.4, -0.2, 0.0, 0.2, 0.4, 0.6, 0.8}));
    const auto segs = extract_isophotes(m, m.normals, camera, options);
    ASSERT_FALSE(segs.empty());
    double worst = 0.0;
    for (const LineSegment& s : segs)
        for (const glm::vec3& p : {s.a, s.b}) {
            const glm::dvec3 q(p);
            const double angle = std::acos(std::clamp(glm::dot(glm::normalize(q), l), -1.0, 1.0));
            worst = std::max(worst, std::abs(angle - std::acos(levels.at(s.isoline))));
            EXPECT_NEAR(glm::length(q), 1.0, 2e-3);  // on the polygon, inside the sphere by a chord
        }
    EXPECT_LT(worst, glm::radians(0.1)) << "degrees: " << glm::degrees(worst);
    const auto loops = chain_segments(segs);
    EXPECT_EQ(loops.size(), levels.size());
    for (const Polyline& loop : loops) EXPECT_TRUE(loop.closed);
}

// rtsc's defaults: a headlight along the camera's z axis, n·l = k/20 for |k| < 20.
TEST(Isophotes, DefaultIsAHeadlightWithRtscsTwentyLevels) {
    const std::vector<double> levels = isophote_levels({});
    ASSERT_EQ(levels.size(), 39u);
    EXPECT_DOUBLE_EQ(levels.front(), -0.95);
    EXPECT_DOUBLE_EQ(levels[19], 0.0);
    EXPECT_DOUBLE_EQ(levels.back(), 0.95);
    const Mesh m = builtin::sphere(64, 128, 1.0f);
    const Camera camera = perspective({-2.0f, 1.0f, 3.0f});
    const glm::dvec3 towards_eye = glm::normalize(glm::dvec3(camera.eye));
    for (const LineSegment& s : extract_isophotes(m, m.normals, camera)) {
        const double c = glm::dot(glm::normalize(glm::dvec3(s.a)), towards_eye);
        EXPECT_NEAR(c, levels.at(s.isoline), 2e-3);
    }
}

// By default, as rtsc, faces whose three corners face away from the eye draw nothing: what is
// left is the back-face drawing without those faces' segments.
TEST(Isophotes, FacesTurnedAwayAreCulledByDefault) {
    const Mesh m = builtin::sphere(64, 128, 1.0f);
    const Camera camera = perspective({1.0f, 1.5f, 4.0f});
    const std::vector<float> ndotv = view_dot_normal(m, m.normals, camera);
    const auto away = [&](uint32_t f) {
        const glm::uvec3 t = m.triangles[f];
        return ndotv[t.x] <= 0.0f && ndotv[t.y] <= 0.0f && ndotv[t.z] <= 0.0f;
    };
    IsophoteOptions options{.direction = {1.0f, 1.0f, 1.0f}, .levels = 5};
    const auto culled = extract_isophotes(m, m.normals, camera, options);
    options.back_faces = true;
    const auto all = extract_isophotes(m, m.normals, camera, options);
    size_t kept = 0, dropped = 0;
    for (const LineSegment& s : all) (away(s.face) ? dropped : kept) += 1;
    EXPECT_GT(dropped, 100u);
    ASSERT_EQ(culled.size(), kept);
    size_t i = 0;
    for (const LineSegment& s : all)
        if (!away(s.face)) {
            EXPECT_EQ(culled[i].face, s.face);
            EXPECT_EQ(culled[i].a, s.a);
            ++i;
        }
}

TEST(Isophotes, ListedValuesWhenLevelsIsZero) {
    // (n·l = −0.25 under this headlight lies beyond the outline: drawn with the back faces.)
    const IsophoteOptions options{.levels = 0, .values = {0.5f, -0.25f, 0.5f, 2.0f}, .back_faces = true};
    EXPECT_EQ(isophote_levels(options), (std::vector<double>{-0.25, 0.5, 1.0}));
    const Mesh m = builtin::sphere(32, 64, 1.0f);
    const Camera camera = perspective({0.0f, 0.0f, 4.0f});
    // n·l = 1 touches the sphere only at the vertex facing the light: a loop of no length.
    size_t drawn = 0;
    for (const Polyline& loop : chain_segments(extract_isophotes(m, m.normals, camera, options))) {
        drawn += polyline_length(loop) > 1e-4f;
    }
    EXPECT_EQ(drawn, 2u);
}

TEST(Isophotes, TheLightTurnsWithTheCamera) {
    const Mesh m = builtin::sphere(32, 64, 1.0f);
    const IsophoteOptions options{.direction = {0.0f, 1.0f, 0.0f}, .levels = 0, .values = {0.5f}};
    for (const glm::vec3& up : {glm::vec3(0, 1, 0), glm::vec3(1, 0, 0)}) {
        const Camera camera = perspective({0.0f, 0.0f, 4.0f}, up);
        const auto segs = extract_isophotes(m, m.normals, camera, options);
        ASSERT_FALSE(segs.empty());
        for (const LineSegment& s : segs)
            EXPECT_NEAR(glm::dot(glm::normalize(glm::dvec3(s.a)), glm::dvec3(up)), 0.5, 5e-3);
    }
}

TEST(Isophotes, BadInput) {
    const Mesh m = builtin::sphere(8, 16, 1.0f);
    const Camera camera = perspective({0.0f, 0.0f, 4.0f});
    EXPECT_THROW(extract_isophotes(m, m.normals, camera, {.direction = glm::vec3(0.0f)}), InputError);
    EXPECT_THROW(extract_isophotes(m, {}, camera), std::invalid_argument);
    Camera broken = camera;
    broken.target = broken.eye;  // no frame: the direction is taken as given, no crash
    EXPECT_NO_THROW(extract_isophotes(m, m.normals, broken));
}

}  // namespace
}  // namespace inkshade::geometry
