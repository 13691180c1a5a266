#include "geometry/contours.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"

namespace inkshade::geometry {
namespace {

constexpr float kImage = 1024.0f;  // image height (and width) in pixels for projected checks

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Pixel coordinates of p in a kImage² image (origin at the centre).
glm::vec2 project(const Camera& camera, const glm::vec3& p) {
    const glm::vec4 clip = camera.projection(1.0f) * camera.view() * glm::vec4(p, 1.0f);
    return glm::vec2(clip) / clip.w * (0.5f * kImage);
}

Camera ortho_camera(const glm::vec3& eye, const glm::vec3& up = {0, 1, 0}) {
    Camera c;
    c.eye = eye;
    c.up = up;
    c.orthographic = true;
    c.ortho_height = 2.5f;
    return c;
}

Camera perspective_camera(const glm::vec3& eye, float fov_degrees) {
    Camera c;
    c.eye = eye;
    c.fov_degrees = fov_degrees;
    return c;
}

// Unit outward normal of the torus around z with major radius R at (or near) p.
glm::vec3 torus_normal(const glm::vec3& p, float R) {
    const glm::vec3 centre = R * glm::normalize(glm::vec3(p.x, p.y, 0.0f));
    return glm::normalize(p - centre);
}

// Eye on a sphere of radius `distance` about the origin at the given azimuth (about +z) and
// elevation, in radians; up stays +z so small orbits move the view smoothly.
Camera orbit(double azimuth, double elevation, double distance) {
    Camera c;
    c.eye = glm::vec3(distance * glm::dvec3(std::cos(elevation) * std::cos(azimuth),
                                            std::cos(elevation) * std::sin(azimuth), std::sin(elevation)));
    c.up = {0, 0, 1};
    c.fov_degrees = 40.0f;
    return c;
}

size_t total_points(const std::vector<Polyline>& lines) {
    size_t n = 0;
    for (const Polyline& l : lines) n += l.points.size();
    return n;
}

TEST(Contours, SphereContourIsUnitCircleOrthographic) {
    const Mesh sphere = builtin::sphere(128, 256, 1.0f);
    // Half a pixel at 1024 px over 2.5 world units.
    const float tol = 0.5f * 2.5f / kImage;
    // Straight down the axis (the equator ring lies exactly on the contour) and oblique.
    for (const glm::vec3 eye : {glm::vec3(0, 0, 5), glm::vec3(1.5f, 2.0f, 4.0f)}) {
        const Camera camera = ortho_camera(eye);
        const auto segs = extract_contours(sphere, sphere.normals, camera);
        ASSERT_GT(segs.size(), 100u);
        const glm::mat4 view = camera.view();
        float worst = 0.0f;
        for (const ContourSegment& s : segs)
            for (const glm::vec3& p : {s.a, s.b}) {
                const glm::vec3 q = glm::vec3(view * glm::vec4(p, 1.0f));
                worst = std::max(worst, std::abs(std::hypot(q.x, q.y) - 1.0f));
                // Also half a pixel in the image the camera makes.
                EXPECT_NEAR(glm::length(project(camera, p)), kImage / 2.5f, 0.5f);
                // And on the analytic contour n·v = 0 (n = p/|p|), not merely near the rim.
                EXPECT_NEAR(glm::dot(glm::normalize(p), glm::normalize(eye)), 0.0f, 1e-3f);
            }
        EXPECT_LT(worst, tol) << "eye " << eye.x << "," << eye.y << "," << eye.z;
    }
}

TEST(Contours, SphereContourIsCircleOfTangencyPerspective) {
    const Mesh sphere = builtin::sphere(128, 256, 1.0f);
    const float d = 4.0f, fov = 40.0f;
    const glm::vec3 dir = glm::normalize(glm::vec3(0.3f, 0.4f, 1.0f));
    const Camera camera = perspective_camera(d * dir, fov);
    const auto segs = extract_contours(sphere, sphere.normals, camera);
    ASSERT_GT(segs.size(), 100u);
    // The cone of tangency has half-angle asin(1/d); the projected circle's radius in pixels.
    const double alpha = std::asin(1.0 / d);
    const double radius_px = std::tan(alpha) / std::tan(glm::radians(double(fov)) / 2.0) * (kImage / 2.0);
    for (const ContourSegment& s : segs)
        for (const glm::vec3& p : {s.a, s.b}) {
            EXPECT_NEAR(glm::length(project(camera, p)), radius_px, 0.5);
            // The circle of tangency: |p| = 1 and p·eye = 1.
            EXPECT_NEAR(glm::length(p), 1.0f, 1e-3f);
            EXPECT_NEAR(glm::dot(p, camera.eye), 1.0f, 5e-3f);
        }
}

TEST(Contours, NeighbouringSegmentsShareEndpointsExactly) {
    const Mesh sphere = builtin::sphere(32, 64, 1.0f);
    const auto segs = extract_contours(sphere, sphere.normals, perspective_camera({1, 2, 3}, 40));
    std::map<uint64_t, glm::vec3> at;
    size_t shared = 0;
    for (const ContourSegment& s : segs) {
        EXPECT_NE(s.edge_a, s.edge_b);
        for (const auto& [key, p] : {std::pair{s.edge_a, s.a}, std::pair{s.edge_b, s.b}}) {
            const auto [it, inserted] = at.emplace(key, p);
            if (!inserted) {
                ++shared;
                EXPECT_EQ(it->second, p);  // bit-identical
            }
        }
    }
    EXPECT_EQ(shared, segs.size());  // closed curve: every key used by exactly two segments
}

TEST(Contours, SegmentsKeepFrontSideOnTheLeft) {
    // Seen from the eye, the front-facing cap of a sphere is inside the contour: walking a → b
    // with the front on the left is counter-clockwise in the image.
    const Mesh sphere = builtin::sphere(32, 64, 1.0f);
    const Camera camera = perspective_camera({0.5f, 1.0f, 4.0f}, 40);
    const auto segs = extract_contours(sphere, sphere.normals, camera);
    ASSERT_FALSE(segs.empty());
    for (const ContourSegment& s : segs) {
        const glm::vec2 a = project(camera, s.a), b = project(camera, s.b);
        if (glm::distance(a, b) < 1e-3f) continue;                      // through a vertex: no direction
        EXPECT_GT(a.x * b.y - a.y * b.x, 0.0f) << glm::distance(a, b);  // centre on the left
    }
}

TEST(Contours, ZeroDotCountsAsPositive) {
    // One triangle: g = 0 at vertex 0 (normal perpendicular to the view), others negative.
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}};
    const std::vector<glm::vec3> normals = {{1, 0, 0}, {0, 0, -1}, {0, 0, -1}};
    const auto segs = extract_contours(m, normals, ortho_camera({0, 0, 5}));
    ASSERT_EQ(segs.size(), 1u);
    // The crossings sit on vertex 0 itself, from both of its edges.
    EXPECT_EQ(segs[0].a, glm::vec3(0.0f));
    EXPECT_EQ(segs[0].b, glm::vec3(0.0f));
    // Vertex 0 is the positive one: a on edge (0, 1), b on edge (2, 0).
    EXPECT_EQ(segs[0].edge_a, edge_key(0, 1));
    EXPECT_EQ(segs[0].edge_b, edge_key(2, 0));
}

TEST(Contours, InterpolatesCrossingAlongEdge) {
    Mesh m;
    m.positions = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
    m.triangles = {{0, 1, 2}};
    // g: 0.75 at 0, −0.25 at 1 and 2 → crossings at t = 0.75 along both edges from 0.
    const std::vector<glm::vec3> normals = {{0, 0, 0.75f}, {0, 0, -0.25f}, {0, 0, -0.25f}};
    const auto segs = extract_contours(m, normals, ortho_camera({0, 0, 5}));
    ASSERT_EQ(segs.size(), 1u);
    EXPECT_EQ(segs[0].face, 0u);
    EXPECT_NEAR(glm::distance(segs[0].a, glm::vec3(3, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(segs[0].b, glm::vec3(0, 3, 0)), 0.0f, 1e-6f);
    EXPECT_THROW(extract_contours(m, {}, ortho_camera({0, 0, 5})), std::invalid_argument);
}

TEST(Contours, OutputIsInFaceOrderAndDeterministic) {
    const Mesh torus = builtin::torus(1.0f, 0.4f, 512, 256);  // > one TBB block of faces
    const Camera camera = orbit(0.3, 0.6, 4.0);
    const auto first = extract_contours(torus, torus.normals, camera);
    ASSERT_GT(first.size(), 100u);
    for (size_t i = 1; i < first.size(); ++i) ASSERT_LT(first[i - 1].face, first[i].face);
    const auto second = extract_contours(torus, torus.normals, camera);
    ASSERT_EQ(first.size(), second.size());
    for (size_t i = 0; i < first.size(); ++i) {
        EXPECT_EQ(first[i].face, second[i].face);
        EXPECT_EQ(first[i].a, second[i].a);
        EXPECT_EQ(first[i].b, second[i].b);
    }
}

TEST(Contours, MeshSilhouetteEdgesSeparateFrontAndBackFaces) {
    const Mesh sphere = builtin::sphere(32, 64, 1.0f);
    const Camera camera = ortho_camera({0.3f, 0.2f, 5.0f});
    const auto edges = mesh_silhouette_edges(sphere, camera);
    ASSERT_GT(edges.size(), 40u);
    const glm::vec3 v = glm::normalize(camera.eye - camera.target);
    for (const SilhouetteEdge& e : edges) {
        EXPECT_LT(e.v0, e.v1);
        // Mesh silhouette edges lie near the smooth contour: |n·v| within about one face.
        const glm::vec3 mid = glm::normalize(sphere.positions[e.v0] + sphere.positions[e.v1]);
        EXPECT_LT(std::abs(glm::dot(mid, v)), 0.1f);
    }
    // A closed surface's silhouette edges form closed loops: every vertex has even degree.
    std::map<uint32_t, int> degree;
    for (const SilhouetteEdge& e : edges) {
        ++degree[e.v0];
        ++degree[e.v1];
    }
    for (const auto& [vertex, d] : degree) EXPECT_EQ(d % 2, 0) << "vertex " << vertex;
}

TEST(Chaining, SphereContourIsOneClosedLoop) {
    const Mesh sphere = builtin::sphere(128, 256, 1.0f);
    for (const Camera& camera : {ortho_camera({0, 0, 5}), perspective_camera({1, 2, 3}, 40)}) {
        const auto segs = extract_contours(sphere, sphere.normals, camera);
        const auto lines = chain_segments(segs);
        ASSERT_EQ(lines.size(), 1u);
        EXPECT_TRUE(lines[0].closed);
        EXPECT_EQ(lines[0].points.size(), segs.size());
        // Contours are full strength; the strengths run parallel to the points.
        EXPECT_EQ(lines[0].strength, std::vector<float>(segs.size(), 1.0f));
        // Consecutive points are close (one face apart), including the closing step.
        const auto& pts = lines[0].points;
        for (size_t i = 0; i < pts.size(); ++i) EXPECT_LT(glm::distance(pts[i], pts[(i + 1) % pts.size()]), 0.1f);
    }
}

TEST(Chaining, TorusAxisViewGivesInnerAndOuterEquators) {
    const float R = 1.0f, r = 0.4f;
    const Mesh torus = builtin::torus(R, r, 128, 64);
    const auto lines = chain_segments(extract_contours(torus, torus.normals, ortho_camera({0, 0, 5})));
    ASSERT_EQ(lines.size(), 2u);
    std::set<int> radii;  // in units of 0.1
    for (const Polyline& l : lines) {
        EXPECT_TRUE(l.closed);
        ASSERT_FALSE(l.points.empty());
        const float radius = std::hypot(l.points[0].x, l.points[0].y);
        for (const glm::vec3& p : l.points) {
            EXPECT_NEAR(std::hypot(p.x, p.y), radius, 1e-3f);
            EXPECT_NEAR(p.z, 0.0f, 1e-3f);
        }
        radii.insert(int(std::lround(radius * 10.0f)));
    }
    EXPECT_EQ(radii, (std::set<int>{6, 14}));  // R − r and R + r
}

TEST(Chaining, TorusObliqueViewLoopsLieOnAnalyticContour) {
    const float R = 1.0f, r = 0.4f;
    const Mesh torus = builtin::torus(R, r, 256, 128);
    const Camera camera = orbit(0.4, 0.5, 4.0);
    const auto lines = chain_segments(extract_contours(torus, torus.normals, camera));
    ASSERT_GE(lines.size(), 2u);
    float worst = 0.0f;
    for (const Polyline& l : lines) {
        EXPECT_TRUE(l.closed);
        for (const glm::vec3& p : l.points) {
            const glm::vec3 v = glm::normalize(camera.eye - p);
            worst = std::max(worst, std::abs(glm::dot(torus_normal(p, R), v)));
        }
    }
    // n·v changes by about 1/r per unit length across the tube; 2e-3 is well under a
    // thousandth of the tube's circumference in position.
    EXPECT_LT(worst, 2e-3f);
    EXPECT_GT(total_points(lines), 500u);
}

TEST(Chaining, CountsStableUnderTinyOrbit) {
    const Mesh torus = builtin::torus(1.0f, 0.4f, 128, 64);
    for (const double elevation : {0.3, 0.5, 1.0}) {
        const auto before = chain_segments(extract_contours(torus, torus.normals, orbit(0.4, elevation, 4.0)));
        const auto after = chain_segments(extract_contours(torus, torus.normals, orbit(0.4 + 1e-4, elevation, 4.0)));
        EXPECT_EQ(before.size(), after.size()) << "elevation " << elevation;
        for (const Polyline& l : after) EXPECT_TRUE(l.closed);
    }
}

TEST(Chaining, OpenChainsAndNonManifoldNodesSplit) {
    // Three faces on edge (0, 1) plus a repeated-index face, an out-of-range face and a
    // NaN normal: g > 0 at 0, 2, 3, 4 and g < 0 at 1.
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, -1, 0}, {0.5f, 0, 1}, {2, 2, 2}};
    m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {1, 1, 2}, {0, 1, 9}, {5, 1, 2}};
    std::vector<glm::vec3> normals = {{0, 0, 1}, {0, 0, -1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {NAN, 0, 0}};
    const auto segs = extract_contours(m, normals, ortho_camera({0, 0, 5}));
    for (const ContourSegment& s : segs) {
        EXPECT_TRUE(finite(s.a) && finite(s.b));
        EXPECT_NE(s.edge_a, s.edge_b);
    }
    // Faces 0, 1, 2 and 5 (vertex 5's NaN counts as g = 0, positive).
    ASSERT_EQ(segs.size(), 4u);
    const auto lines = chain_segments(segs);
    // Node (0,1) has degree 3: three chains end there. Faces 0 and 5 share node (1,2), which
    // has degree 2, so they form one chain of three points.
    ASSERT_EQ(lines.size(), 3u);
    size_t points = 0;
    for (const Polyline& l : lines) {
        EXPECT_FALSE(l.closed);
        points += l.points.size();
        for (const glm::vec3& p : l.points) EXPECT_TRUE(finite(p));
    }
    EXPECT_EQ(points, 2u + 2u + 3u);
    EXPECT_TRUE(chain_segments({}).empty());
    // A segment whose ends share a key is dropped rather than looping on itself.
    ContourSegment self;
    self.edge_a = self.edge_b = 7;
    EXPECT_TRUE(chain_segments({self}).empty());
}

TEST(Chaining, ChainsFollowSegmentDirection) {
    // Three collinear segments listed out of order; the first chain end met in segment order
    // is node 13 (segment 1's b end), so the walk runs b → a and is reversed to run a → b.
    std::vector<ContourSegment> segs(3);
    segs[0] = {{1, 0, 0}, {2, 0, 0}, 11, 12, 0};
    segs[1] = {{2, 0, 0}, {3, 0, 0}, 12, 13, 1};
    segs[2] = {{0, 0, 0}, {1, 0, 0}, 10, 11, 2};
    const auto lines = chain_segments(segs);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_FALSE(lines[0].closed);
    ASSERT_EQ(lines[0].points.size(), 4u);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(lines[0].points[i], glm::vec3(float(i), 0, 0));
}

}  // namespace
}  // namespace inkshade::geometry
