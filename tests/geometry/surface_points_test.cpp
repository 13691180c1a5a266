// The surface location of a drawing's points (LinePath::surface): perspective-correct between
// points, each chain point's face, barycentric weights that give the point back, and the image
// tangents and normals --lines-json-detail full writes (path_tangents).
#include "geometry/surface_points.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/path_attributes.hpp"
#include "stroke_paths.hpp"

namespace inkshade::geometry {
namespace {

glm::vec2 image_point(const ImageProjection& view, glm::vec3 p) {
    const glm::dvec3 q = view.project(p);
    return {float(q.x), float(q.y)};
}

TEST(SurfacePoints, InterpolationIsPerspectiveCorrect) {
    Camera camera;
    camera.eye = {0.0f, 0.5f, 3.0f};
    camera.fov_degrees = 60.0f;
    const ImageProjection view(camera, 640, 480);
    // A piece running from near the eye into the distance: its image midpoint is not the
    // projection of its world midpoint.
    const glm::vec3 a(-0.5f, 0.0f, 2.0f), b(0.8f, -0.2f, -6.0f);
    const SurfacePoint sa{.world = a, .face = 7, .barycentric = {}, .w = float(view.clip_w(a))};
    const SurfacePoint sb{.world = b, .face = 9, .barycentric = {}, .w = float(view.clip_w(b))};
    EXPECT_NEAR(sa.w, view.view_depth(a), 1e-4);  // perspective: w is the view depth
    const glm::vec2 pa = image_point(view, a), pb = image_point(view, b);
    for (float f : {0.1f, 0.25f, 0.5f, 0.9f}) {
        const SurfacePoint s = interpolated(sa, sb, f);
        const glm::vec2 expected = pa + (pb - pa) * f;
        EXPECT_LT(glm::length(image_point(view, s.world) - expected), 1e-3f) << f;
        EXPECT_EQ(s.face, 7) << "the face of the piece from a";
        EXPECT_NEAR(s.w, view.clip_w(s.world), 1e-4 * s.w);
        // The plain linear mix would be far off: the check above is not trivially met.
        EXPECT_GT(glm::length(image_point(view, a + (b - a) * f) - expected), 5.0f) << f;
    }
    // Orthographic: w = 1, the linear mix.
    camera.orthographic = true;
    EXPECT_DOUBLE_EQ(ImageProjection(camera, 640, 480).clip_w(b), 1.0);
}

TEST(SurfacePoints, ChainFacesAndBarycentricsGiveThePointsBack) {
    // Two triangles sharing the edge (1, 2), and a line crossing both: segment 0 on face 0 from
    // the middle of edge (0, 1) to the middle of the shared edge, segment 1 on face 1 onwards.
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 1}};
    mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
    const glm::vec3 m01(1, 0, 0), m12(1, 1, 0), m23(1, 2, 0.5f);
    std::vector<LineSegment> segments(2);
    segments[0] = {.a = m01, .b = m12, .edge_a = 1, .edge_b = 2, .face = 0};
    segments[1] = {.a = m23, .b = m12, .edge_a = 3, .edge_b = 2, .face = 1};  // reversed in the chain
    const std::vector<Polyline> chains = chain_segments(segments, /*faces=*/true);
    ASSERT_EQ(chains.size(), 1u);
    ASSERT_EQ(chains[0].points.size(), 3u);
    EXPECT_EQ(chains[0].faces, (std::vector<uint32_t>{0, 1, 1}));
    EXPECT_TRUE(chain_segments(segments).front().faces.empty()) << "only when asked";

    Camera camera;
    camera.eye = {1.0f, 1.0f, 6.0f};
    camera.target = {1.0f, 1.0f, 0.0f};
    const ImageProjection view(camera, 100, 100);
    LinePath path;
    path.surface = surface_points(chains[0], view);
    path.surface.push_back({.world = {5, 5, 5}, .face = -1, .barycentric = {}, .w = 1.0f});  // a loose point
    std::vector<LinePath> paths{path};
    fill_barycentrics(mesh, paths);
    for (size_t i = 0; i < 3; ++i) {
        const SurfacePoint& s = paths[0].surface[i];
        const glm::uvec3 t = mesh.triangles[size_t(s.face)];
        const glm::vec3 back = s.barycentric.x * mesh.positions[t.x] + s.barycentric.y * mesh.positions[t.y] +
                               s.barycentric.z * mesh.positions[t.z];
        EXPECT_LT(glm::length(back - s.world), 1e-6f) << i;
        EXPECT_NEAR(s.barycentric.x + s.barycentric.y + s.barycentric.z, 1.0f, 1e-6f);
        EXPECT_NEAR(s.w, view.clip_w(s.world), 1e-5);
    }
    // A point on a mesh edge has a weight 0: the middle of edge (0, 1) on face 0.
    EXPECT_NEAR(paths[0].surface[0].barycentric.z, 0.0f, 1e-7f);
    EXPECT_EQ(paths[0].surface[3].barycentric, glm::vec3(0.0f));
}

TEST(PathTangents, UnitAlongTheFiniteDifferencesNormalOnTheRight) {
    // A circle counter-clockwise on screen: the tangent is perpendicular to the radius and the
    // normal (turned +90 degrees in y-down image coordinates: the walk's right-hand side on
    // screen) points out of it, the inside being on the walk's left.
    const glm::vec2 centre(50, 50);
    const LinePath circle = test::circle_path(centre, 20.0f, 64);
    const std::vector<glm::vec2> t = path_tangents(circle);
    ASSERT_EQ(t.size(), circle.points.size());
    for (size_t i = 0; i < t.size(); ++i) {
        const glm::vec2 radial = glm::normalize(circle.points[i] - centre);
        EXPECT_NEAR(glm::length(t[i]), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(t[i], radial), 0.0f, 1e-5f) << i;
        EXPECT_NEAR(glm::dot(path_normal(t[i]), radial), 1.0f, 1e-5f) << i;
    }
    // Moving right, the normal points down the image (+y).
    LinePath line = test::straight_path({0, 0}, {10, 0}, 2.0f);
    line.points.insert(line.points.begin() + 2, line.points[2]);  // a repeated point
    for (const glm::vec2 v : path_tangents(line)) {
        EXPECT_EQ(v, glm::vec2(1, 0));
        EXPECT_EQ(path_normal(v), glm::vec2(0, 1));
    }
    // Straight back: the forward difference; one point: (1, 0).
    LinePath back;
    back.points = {{0, 0}, {0, 4}, {0, 0}};
    EXPECT_EQ(path_tangents(back)[1], glm::vec2(0, -1));
    back.points = {{3, 3}};
    EXPECT_EQ(path_tangents(back), std::vector<glm::vec2>{glm::vec2(1, 0)});
}

}  // namespace
}  // namespace inkshade::geometry
