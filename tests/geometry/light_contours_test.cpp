// light-contour: on the unit sphere n = p at the vertices, so n·l interpolated along an edge is
// p·l there too: the directional light's contour is the great circle p·l = 0, and a point
// light's (n·(l_pos − p) = 0) the circle where the cone from the light touches the sphere,
// p·u = 1 / d for the light at d u.
#include "geometry/light_contours.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"
#include "geometry/visibility.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {
namespace {

constexpr int kSize = 400;

Camera camera_at(const glm::vec3& eye) {
    Camera c;
    c.eye = eye;
    c.target = glm::vec3(0.0f);
    c.fov_degrees = 35.0f;
    c.near_plane = 0.5f;
    c.far_plane = 20.0f;
    return c;
}

Light directional(const glm::vec3& towards_light) {
    Light l;
    l.type = LightType::Directional;
    l.position = towards_light;
    l.target = glm::vec3(0.0f);
    return l;
}

// Points of the circle {p : p·u = h, |p| = 1}, 2048 of them.
std::vector<glm::dvec3> circle(const glm::dvec3& u, double h) {
    const glm::dvec3 a = glm::normalize(glm::cross(u, std::abs(u.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 b = glm::cross(u, a);
    const double rho = std::sqrt(1.0 - h * h);
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 2048; ++i) {
        const double t = 2.0 * M_PI * i / 2048;
        points.push_back(h * u + rho * (std::cos(t) * a + std::sin(t) * b));
    }
    return points;
}

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

// Image distance from p to the nearest drawn path (its segments, and closing segments).
double distance_to_paths(const std::vector<LinePath>& paths, glm::vec2 p) {
    double nearest = 1e30;
    for (const LinePath& path : paths) {
        const size_t n = path.points.size();
        for (size_t i = 0; i + 1 < n + (path.closed ? 1 : 0); ++i)
            nearest = std::min(nearest, distance_to_segment(p, path.points[i], path.points[(i + 1) % n]));
    }
    return nearest;
}

// The drawn light contour covers the part of the circle the camera sees (its front side, away
// from the outline by a margin), within 1 px, and nothing else.
void expect_covers_visible_circle(const Mesh& sphere, const Camera& camera, const Light& light,
                                  const std::vector<glm::dvec3>& points) {
    LineExtractor extractor(sphere);
    const LineDrawing drawing =
        extractor.draw(camera, kSize, kSize, {{"light-contour", {}}}, nullptr, nullptr, {.light = light});
    ASSERT_EQ(drawing.layers.size(), 1u);
    std::vector<glm::vec2> drawn;
    for (const LinePath& p : drawing.layers[0].visible) drawn.insert(drawn.end(), p.points.begin(), p.points.end());
    ASSERT_FALSE(drawn.empty());
    const ImageProjection view(camera, kSize, kSize);
    std::vector<glm::vec2> expected;
    size_t seen = 0;
    for (const glm::dvec3& p : points) {
        const glm::dvec3 s = view.project(glm::vec3(p));
        expected.emplace_back(float(s.x), float(s.y));
        const double facing = glm::dot(p, glm::normalize(glm::dvec3(camera.eye) - p));
        if (facing < 0.1) continue;  // hidden, or too near the outline to tell
        ++seen;
        const double nearest = distance_to_paths(drawing.layers[0].visible, expected.back());
        EXPECT_LT(nearest, 1.0) << "visible circle point " << p.x << "," << p.y << "," << p.z << " not drawn";
    }
    EXPECT_GT(seen, 300u);
    for (const glm::vec2& q : drawn) {
        double nearest = 1e30;
        for (const glm::vec2& e : expected) nearest = std::min(nearest, double(glm::length(q - e)));
        EXPECT_LT(nearest, 1.0) << "drawn point off the circle";
    }
}

TEST(LightContours, DirectionalLightGivesTheGreatCircleNormalToIt) {
    const Mesh sphere = builtin::sphere(64, 128, 1.0f);
    const glm::dvec3 u = glm::normalize(glm::dvec3(1.0, 2.0, 0.5));
    const Light light = directional(glm::vec3(u) * 10.0f);
    const std::vector<LineSegment> segments = extract_light_contours(sphere, sphere.normals, light);
    ASSERT_FALSE(segments.empty());
    for (const LineSegment& s : segments)
        for (const glm::vec3& p : {s.a, s.b}) {
            EXPECT_NEAR(glm::dot(glm::dvec3(p), u), 0.0, 1e-5);
            EXPECT_NEAR(glm::length(glm::dvec3(p)), 1.0, 2e-3);  // on the polygon, inside by a chord
        }
    const std::vector<Polyline> loops = chain_segments(segments);
    ASSERT_EQ(loops.size(), 1u);
    EXPECT_TRUE(loops[0].closed);
    expect_covers_visible_circle(sphere, camera_at({0.5f, 1.0f, 5.0f}), light, circle(u, 0.0));
}

TEST(LightContours, PointLightGivesTheCircleOfTangency) {
    const Mesh sphere = builtin::sphere(64, 128, 1.0f);
    const glm::dvec3 u = glm::normalize(glm::dvec3(-1.0, 1.0, 2.0));
    const double d = 2.5;
    Light light;
    light.type = LightType::Point;
    light.position = glm::vec3(d * u);
    const std::vector<LineSegment> segments = extract_light_contours(sphere, sphere.normals, light);
    ASSERT_FALSE(segments.empty());
    for (const LineSegment& s : segments)
        for (const glm::vec3& p : {s.a, s.b}) EXPECT_NEAR(glm::dot(glm::dvec3(p), u), 1.0 / d, 1e-5);
    expect_covers_visible_circle(sphere, camera_at({0.0f, 1.0f, 5.0f}), light, circle(u, 1.0 / d));
}

TEST(LightContours, DefaultLightIsTheKeyLight) {
    // Without a light in the context the drawing follows default_light, as the renderer does.
    const Mesh sphere = builtin::sphere(32, 64, 1.0f);
    const Camera camera = camera_at({0.0f, 0.0f, 5.0f});
    LineExtractor extractor(sphere);
    const Light key = default_light(sphere.bounds(), camera);
    const LineDrawing a = extractor.draw(camera, kSize, kSize, {{"light-contour", {}}});
    const LineDrawing b =
        extractor.draw(camera, kSize, kSize, {{"light-contour", {}}}, nullptr, nullptr, {.light = key});
    ASSERT_FALSE(a.layers[0].visible.empty());
    EXPECT_EQ(a.layers[0].visible.size(), b.layers[0].visible.size());
    EXPECT_EQ(a.layers[0].visible[0].points, b.layers[0].visible[0].points);
}

}  // namespace
}  // namespace inkshade::geometry
