// cast-shadow: a sphere of radius r, centre c, over a plane n·x = d under a directional light
// towards u casts the shadow {x : the line x + t u passes within r of c}, whose boundary is the
// ellipse where the light rays tangent to the sphere meet the plane: the projection of the
// sphere's light-contour great circle (c + r (cos θ e1 + sin θ e2), e1, e2 ⟂ u) along u.
#include "geometry/cast_shadows.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analytic_meshes.hpp"
#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"
#include "geometry/visibility.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {
namespace {

struct Scene {
    Mesh mesh;
    glm::dvec3 n, c, u;  // plane normal (plane through the origin), sphere centre, towards the light
    double r = 1.0;
};

// A unit UV sphere floating over a tilted square plane of 200 x 200 cells, 8 units wide.
Scene sphere_over_plane() {
    Scene s;
    s.n = glm::normalize(glm::dvec3(0.1, 1.0, 0.2));
    s.u = glm::normalize(glm::dvec3(0.5, 1.0, -0.3));
    s.c = 2.5 * s.n + glm::dvec3(0.2, 0.0, 0.1);
    const glm::dvec3 e1 = glm::normalize(glm::cross(s.n, glm::dvec3(0, 0, 1))), e2 = glm::cross(e1, s.n);
    const int cells = 200;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            const double x = -4.0 + 8.0 * i / cells, y = -4.0 + 8.0 * j / cells;
            s.mesh.positions.emplace_back(x * e1 + y * e2);
            s.mesh.normals.emplace_back(s.n);
        }
    test::add_grid_triangles(s.mesh, cells, cells);  // counter-clockwise seen from e1 × e2 = n
    const Mesh ball = builtin::sphere(64, 128, float(s.r));
    const uint32_t base = uint32_t(s.mesh.positions.size());
    for (size_t v = 0; v < ball.positions.size(); ++v) {
        s.mesh.positions.push_back(ball.positions[v] + glm::vec3(s.c));
        s.mesh.normals.push_back(ball.normals[v]);
    }
    for (const glm::uvec3& t : ball.triangles) s.mesh.triangles.push_back(t + base);
    return s;
}

Light directional(const glm::dvec3& towards_light) {
    Light l;
    l.type = LightType::Directional;
    l.position = glm::vec3(towards_light * 10.0);
    l.target = glm::vec3(0.0f);
    return l;
}

// The ellipse: the great circle normal to u projected along u onto the plane.
std::vector<glm::dvec3> shadow_ellipse(const Scene& s, int count) {
    const glm::dvec3 a = glm::normalize(glm::cross(s.u, glm::dvec3(1, 0, 0))), b = glm::cross(s.u, a);
    std::vector<glm::dvec3> points;
    for (int i = 0; i < count; ++i) {
        const double t = 2.0 * M_PI * i / count;
        const glm::dvec3 q = s.c + s.r * (std::cos(t) * a + std::sin(t) * b);
        points.push_back(q - s.u * (glm::dot(s.n, q) / glm::dot(s.n, s.u)));
    }
    return points;
}

double distance_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

TEST(CastShadows, SphereOnAPlaneCastsTheEllipseOfTheProjection) {
    const Scene s = sphere_over_plane();
    const RayScene scene(s.mesh);
    const std::vector<LineSegment> segments = extract_cast_shadows(s.mesh, s.mesh.normals, directional(s.u), scene);
    ASSERT_FALSE(segments.empty());
    for (const LineSegment& seg : segments)
        for (const glm::vec3& p : {seg.a, seg.b}) {
            EXPECT_NEAR(glm::dot(s.n, glm::dvec3(p)), 0.0, 1e-5) << "not on the plane";
            // On the shadow's boundary: the ray from p towards the light grazes the sphere
            // (the polygon lies inside the sphere by its chords, ~6e-4).
            const glm::dvec3 w = glm::dvec3(p) - s.c;
            const double dist = glm::length(w - glm::dot(w, s.u) * s.u);
            EXPECT_NEAR(dist, s.r, 2e-3);
        }
    // Covered: every point of the ellipse lies on a segment, to the plane grid's chords.
    for (const glm::dvec3& e : shadow_ellipse(s, 720)) {
        double nearest = 1e30;
        for (const LineSegment& seg : segments)
            nearest = std::min(nearest, distance_to_segment(e, glm::dvec3(seg.a), glm::dvec3(seg.b)));
        EXPECT_LT(nearest, 5e-3) << "ellipse point " << e.x << "," << e.y << "," << e.z << " not covered";
    }
    // One closed boundary.
    const std::vector<Polyline> loops = chain_segments(segments);
    ASSERT_EQ(loops.size(), 1u);
    EXPECT_TRUE(loops[0].closed);
}

TEST(CastShadows, PointLightEndsItsRaysAtTheLight) {
    // A light between the sphere and the plane: the sphere is behind the light, no shadow.
    const Scene s = sphere_over_plane();
    const RayScene scene(s.mesh);
    Light light;
    light.type = LightType::Point;
    light.position = glm::vec3(s.c - 1.5 * s.n);
    EXPECT_TRUE(extract_cast_shadows(s.mesh, s.mesh.normals, light, scene).empty());
    light.position = glm::vec3(s.c + 3.0 * s.n);  // above it: a shadow
    EXPECT_FALSE(extract_cast_shadows(s.mesh, s.mesh.normals, light, scene).empty());
}

TEST(CastShadows, DrawnWhereTheCameraSeesIt) {
    const Scene s = sphere_over_plane();
    Camera camera;
    camera.eye = glm::vec3(s.n * 9.0 + glm::dvec3(1.0, 0.0, 4.0));
    camera.target = glm::vec3(0.0f);
    camera.fov_degrees = 50.0f;
    camera.near_plane = 0.5f;
    camera.far_plane = 40.0f;
    LineExtractor extractor(s.mesh);
    const LineDrawing drawing =
        extractor.draw(camera, 400, 400, {{"cast-shadow", {}}}, nullptr, nullptr, {.light = directional(s.u)});
    ASSERT_EQ(drawing.layers.size(), 1u);
    ASSERT_FALSE(drawing.layers[0].visible.empty());
    const ImageProjection view(camera, 400, 400);
    std::vector<glm::dvec2> ellipse;
    for (const glm::dvec3& e : shadow_ellipse(s, 4096)) ellipse.emplace_back(view.project(glm::vec3(e)));
    size_t drawn = 0;
    for (const LinePath& path : drawing.layers[0].visible)
        for (const glm::vec2& q : path.points) {
            double nearest = 1e30;
            for (const glm::dvec2& e : ellipse) nearest = std::min(nearest, glm::length(glm::dvec2(q) - e));
            EXPECT_LT(nearest, 1.0) << "drawn point off the ellipse";
            ++drawn;
        }
    EXPECT_GT(drawn, 50u);
}

}  // namespace
}  // namespace inkshade::geometry
