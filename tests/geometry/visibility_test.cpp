#include "geometry/visibility.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <optional>

#include "geometry/builtin_models.hpp"
#include "geometry/normals.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {
namespace {

constexpr int kWidth = 400, kHeight = 300;

Camera camera_at(const glm::vec3& eye, const glm::vec3& up) {
    Camera c;
    c.eye = eye;
    c.target = glm::vec3(0.0f);
    c.up = up;
    c.fov_degrees = 40.0f;
    c.near_plane = 0.5f;
    c.far_plane = 20.0f;
    return c;
}

// World point of an image point (x, y px, window depth): the inverse of ImageProjection.
glm::dvec3 unproject(const Camera& camera, glm::vec2 p, float depth) {
    const glm::dmat4 m = glm::dmat4(camera.projection(float(kWidth) / float(kHeight))) * glm::dmat4(camera.view());
    const glm::dvec4 ndc(2.0 * p.x / kWidth - 1.0, 1.0 - 2.0 * p.y / kHeight, 2.0 * double(depth) - 1.0, 1.0);
    const glm::dvec4 w = glm::inverse(m) * ndc;
    return glm::dvec3(w) / w.w;
}

// The builtin torus (around z, R = 1, r = 0.4): negative inside.
double torus_implicit(const glm::dvec3& q) {
    const double R = 1.0, r = 0.4;
    const double s = glm::dot(q, q) + R * R - r * r;
    return s * s - 4.0 * R * R * (q.x * q.x + q.y * q.y);
}

// Analytic visibility: does the segment from `eye` to p pass inside the smooth torus before
// coming within `slack` of p? Marched in 1e-3 steps (a grazing chord shorter than that would
// need a depth below 1e-6). The slack covers the mesh's chords lying up to ~5e-4 inside the
// smooth surface: a ray grazing such a point enters the smooth torus ~0.02 before it.
bool torus_hides(const glm::dvec3& eye, const glm::dvec3& p, double slack) {
    const glm::dvec3 d = p - eye;
    const double len = glm::length(d);
    for (double s = 0.0; s < len - slack; s += 1e-3)
        if (torus_implicit(eye + d * (s / len)) < 0.0) return true;
    return false;
}

// Arc length (px) from each point of an open path to its nearer end; loops: infinity.
std::vector<double> distance_to_ends(const LinePath& path) {
    const size_t n = path.points.size();
    std::vector<double> from_start(n, 0.0), out(n, 1e30);
    for (size_t i = 1; i < n; ++i) from_start[i] = from_start[i - 1] + glm::length(path.points[i] - path.points[i - 1]);
    if (path.closed) return out;
    for (size_t i = 0; i < n; ++i) out[i] = std::min(from_start[i], from_start[n - 1] - from_start[i]);
    return out;
}

// The contour of a torus seen from low above its plane (the inner contour passes behind the
// tube): every point farther than 2 px (along its path) from a visibility change must agree
// with the analytic answer; nearer ones may differ by the mesh-vs-torus discrepancy.
void expect_torus_contour_matches_analytic(bool orthographic) {
    const Mesh torus = builtin::torus();
    Camera camera = camera_at({0.3f, -3.2f, 1.2f}, {0, 0, 1});  // ~20° above its plane
    camera.orthographic = orthographic;
    camera.ortho_height = 3.0f;
    LineExtractor extractor(torus);
    const LineDrawing drawing = extractor.draw(camera, kWidth, kHeight, {{"contour", {{"hidden", {1.0f}}}}});
    const LineLayer& layer = drawing.layers.at(0);
    ASSERT_FALSE(layer.visible.empty());
    ASSERT_FALSE(layer.hidden.empty()) << "the inner contour passes behind the tube";

    const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target) - glm::dvec3(camera.eye));
    size_t checked = 0, hidden_points = 0, disagree = 0;
    for (bool hidden : {false, true}) {
        for (const LinePath& path : hidden ? layer.hidden : layer.visible) {
            const std::vector<double> ends = distance_to_ends(path);
            for (size_t i = 0; i < path.points.size(); ++i) {
                if (ends[i] < 2.0) continue;
                const glm::dvec3 p = unproject(camera, path.points[i], path.depth[i]);
                // Orthographic rays come along the view direction from outside the torus.
                const glm::dvec3 from = orthographic ? p - 5.0 * forward : glm::dvec3(camera.eye);
                ++checked;
                hidden_points += hidden;
                if (torus_hides(from, p, 0.05) != hidden) ++disagree;
            }
        }
    }
    EXPECT_GT(checked, 500u);
    EXPECT_GT(hidden_points, checked / 10) << "a substantial part of the contour is hidden";
    EXPECT_EQ(disagree, 0u) << "of " << checked << " points";
}

TEST(Visibility, TorusHiddenContoursMatchAnalyticRayCasting) {
    expect_torus_contour_matches_analytic(false);
    expect_torus_contour_matches_analytic(true);
}

// A sphere (radius 0.4, centre (0, −1, 1)) floats in front of the bottom border of a square
// plate z = 0, |x|, |y| ≤ 1, seen from (0, 0, 5): the middle of that border is hidden.
Mesh sphere_in_front_of_plate() {
    Mesh m = builtin::sphere(64, 128, 0.4f);
    for (auto& p : m.positions) p += glm::vec3(0.0f, -1.0f, 1.0f);
    const uint32_t base = uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
    m.triangles.push_back({base, base + 1, base + 2});
    m.triangles.push_back({base, base + 2, base + 3});
    m.normals.clear();
    return m;
}

TEST(Visibility, SphereHidesPartOfPlateBorder) {
    const Mesh mesh = sphere_in_front_of_plate();
    const Camera camera = camera_at({0.0f, 0.0f, 5.0f}, {0, 1, 0});
    LineExtractor extractor(mesh);
    const LineDrawing drawing = extractor.draw(camera, kWidth, kHeight, {{"border", {{"hidden", {1.0f}}}}});
    const LineLayer& layer = drawing.layers.at(0);
    ASSERT_EQ(layer.hidden.size(), 1u);
    ASSERT_EQ(layer.visible.size(), 1u) << "the rest of the loop is one open path";
    EXPECT_FALSE(layer.visible[0].closed);
    const LinePath& hidden = layer.hidden[0];
    ASSERT_EQ(hidden.points.size(), 2u);

    // Analytic ends: the border point (x, −1, 0) is hidden while the ray from the eye meets
    // the sphere; the tangent ray has distance exactly 0.4 from the centre.
    const glm::dvec3 eye(0, 0, 5), centre(0, -1, 1);
    auto ray_distance = [&](double x) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(x, -1, 0) - eye);
        const glm::dvec3 c = centre - eye;
        return glm::length(c - glm::dot(c, d) * d);
    };
    double lo = 0.0, hi = 1.0;  // ray_distance grows with |x|
    for (int i = 0; i < 60; ++i) ((ray_distance(0.5 * (lo + hi)) < 0.4) ? lo : hi) = 0.5 * (lo + hi);
    const ImageProjection view(camera, kWidth, kHeight);
    const double x_end = view.project(glm::vec3(float(lo), -1.0f, 0.0f)).x;
    const double x_start = view.project(glm::vec3(float(-lo), -1.0f, 0.0f)).x;
    const double left = std::min(hidden.points[0].x, hidden.points[1].x);
    const double right = std::max(hidden.points[0].x, hidden.points[1].x);
    // The mesh's outline lies inside the smooth sphere's by its sagitta (~0.1 px here).
    EXPECT_NEAR(left, x_start, 0.25);
    EXPECT_NEAR(right, x_end, 0.25);
    EXPECT_NEAR(hidden.points[0].y, view.project(glm::vec3(0, -1, 0)).y, 1e-3);
}

// Brute force: does the segment eye → p cross any triangle of `mesh` (Möller–Trumbore)?
bool mesh_hides(const Mesh& mesh, const glm::dvec3& eye, const glm::dvec3& p) {
    const glm::dvec3 d = p - eye;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
        const glm::dvec3 e1 = b - a, e2 = c - a, h = glm::cross(d, e2);
        const double det = glm::dot(e1, h);
        if (std::abs(det) < 1e-15) continue;
        const glm::dvec3 s = eye - a;
        const double u = glm::dot(s, h) / det;
        const glm::dvec3 q = glm::cross(s, e1);
        const double v = glm::dot(d, q) / det, t_hit = glm::dot(e2, q) / det;
        if (u >= 0 && v >= 0 && u + v <= 1 && t_hit > 0 && t_hit < 1 - 1e-9) return true;
    }
    return false;
}

TEST(Visibility, SplitPointsAreSubPixelAccurate) {
    // One long segment along the plate's bottom border (vertex keys of the plate's corners);
    // its split points must match a brute-force bisection against every triangle within half
    // VisibilityOptions::transition_precision_px (the middle of the last bracket) plus float
    // rounding, at the default 1/16 px and at 0.01 px.
    const Mesh mesh = sphere_in_front_of_plate();
    const Camera camera = camera_at({0.0f, 0.0f, 5.0f}, {0, 1, 0});
    const ImageProjection view(camera, kWidth, kHeight);
    const RayScene scene(mesh);
    const uint32_t base = uint32_t(mesh.positions.size()) - 4;
    LineSegment s;
    s.a = mesh.positions[base];
    s.b = mesh.positions[base + 1];
    s.edge_a = vertex_key(base);
    s.edge_b = vertex_key(base + 1);
    s.face = uint32_t(mesh.triangles.size()) - 2;
    for (const float precision : {VisibilityOptions{}.transition_precision_px, 0.01f}) {
        VisibilityOptions options;
        options.transition_precision_px = precision;
        const VisibilitySplit split = split_by_visibility(scene, mesh, view, {s}, options);
        ASSERT_EQ(split.visible.size(), 2u);
        ASSERT_EQ(split.hidden.size(), 1u);
        EXPECT_EQ(split.visible[0].edge_a, s.edge_a);  // unsplit ends keep their node keys
        EXPECT_EQ(split.visible[1].edge_b, s.edge_b);
        EXPECT_NE(split.hidden[0].edge_a, split.hidden[0].edge_b);

        const glm::dvec3 eye(camera.eye);
        for (double sign : {-1.0, 1.0}) {
            double lo = 0.0, hi = sign;  // hidden at x = 0, visible at x = ±1
            for (int i = 0; i < 50; ++i) {
                const double mid = 0.5 * (lo + hi);
                (mesh_hides(mesh, eye, {mid, -1, 0}) ? lo : hi) = mid;
            }
            const double expected = view.project(glm::vec3(float(lo), -1.0f, 0.0f)).x;
            const glm::vec3 end = sign < 0 ? split.hidden[0].a : split.hidden[0].b;
            EXPECT_NEAR(view.project(end).x, expected, 0.5 * precision + 1e-3) << "side " << sign << ", " << precision;
        }
    }
}

TEST(Visibility, ShortWholeChainsAreLeftOutUntestedAndNothingElseChanges) {
    // Lines in front of (z = 0.5) and behind (z = −0.5) the plate z = 0 seen from (0, 0, 5),
    // about 92 px to a world unit here. Node keys name edges of vertices the mesh does not have,
    // so the segments lie on no face.
    const Mesh mesh = sphere_in_front_of_plate();
    const Camera camera = camera_at({0.0f, 0.0f, 5.0f}, {0, 1, 0});
    const ImageProjection view(camera, kWidth, kHeight);
    const RayScene scene(mesh);
    auto node = [](uint32_t k) { return edge_key(1000000 + k, 2000000 + k); };
    auto line = [&](glm::vec3 a, glm::vec3 b, uint32_t ka, uint32_t kb) {
        LineSegment s;
        s.a = a, s.b = b, s.edge_a = node(ka), s.edge_b = node(kb);
        return s;
    };
    const std::vector<LineSegment> segments = {
        // 0-1: a free run 0.03 long (~2.8 px) in front: left out at min-length 4.
        line({0.50f, 0.5f, 0.5f}, {0.515f, 0.5f, 0.5f}, 1, 2), line({0.515f, 0.5f, 0.5f}, {0.53f, 0.5f, 0.5f}, 2, 3),
        // 2-4: the same short run ending at a junction (node 20) with two long ones: kept.
        line({-0.53f, 0.5f, 0.5f}, {-0.5f, 0.5f, 0.5f}, 21, 20), line({-0.5f, 0.5f, 0.5f}, {0.0f, 0.5f, 0.5f}, 20, 22),
        line({-0.5f, 0.5f, 0.5f}, {-0.5f, 0.0f, 0.5f}, 20, 23),
        // 5-7: a loop 0.03 around (~2.8 px): left out.
        line({0.2f, 0.2f, 0.5f}, {0.21f, 0.2f, 0.5f}, 30, 31), line({0.21f, 0.2f, 0.5f}, {0.2f, 0.21f, 0.5f}, 31, 32),
        line({0.2f, 0.21f, 0.5f}, {0.2f, 0.2f, 0.5f}, 32, 30),
        // 8: a long line behind the plate (hidden), 9: a short one behind it (left out).
        line({-0.5f, -0.2f, -0.5f}, {0.5f, -0.2f, -0.5f}, 40, 41), line({0.3f, 0.3f, -0.5f}, {0.32f, 0.3f, -0.5f}, 50, 51)};
    VisibilityOptions all, trimmed;
    trimmed.min_length_px = 4.0f;
    EXPECT_GT(view.project(segments[1].b).x - view.project(segments[0].a).x, 2.0);
    const VisibilitySplit a = split_by_visibility(scene, mesh, view, segments, all);
    const VisibilitySplit b = split_by_visibility(scene, mesh, view, segments, trimmed);
    auto keys = [](const std::vector<LineSegment>& list) {
        std::vector<uint64_t> out;
        for (const LineSegment& s : list) out.push_back(s.edge_a);
        return out;
    };
    EXPECT_EQ(keys(a.visible), (std::vector<uint64_t>{node(1), node(2), node(21), node(20), node(20), node(30), node(31),
                                                      node(32)}));
    EXPECT_EQ(keys(a.hidden), (std::vector<uint64_t>{node(40), node(50)}));
    EXPECT_EQ(keys(b.visible), (std::vector<uint64_t>{node(21), node(20), node(20)}));
    EXPECT_EQ(keys(b.hidden), (std::vector<uint64_t>{node(40)}));
    EXPECT_EQ(b.hidden_levels, std::vector<uint8_t>{1});
    // What is kept is exactly what the untrimmed split gives for those segments.
    for (size_t i = 0; i < b.visible.size(); ++i) {
        EXPECT_EQ(b.visible[i].a, a.visible[2 + i].a);
        EXPECT_EQ(b.visible[i].b, a.visible[2 + i].b);
    }
}

TEST(Visibility, PointsOnTheFrontSurfaceAreVisibleAndBehindAreHidden) {
    const Mesh sphere = builtin::sphere();
    const RayScene scene(sphere);
    const Camera camera = camera_at({0.0f, 0.0f, 4.0f}, {0, 1, 0});
    const ImageProjection view(camera, kWidth, kHeight);
    // Vertex closest to the eye (the pole ring at +z is not on the UV sphere's axis, so search).
    uint32_t front = 0, back = 0;
    for (uint32_t v = 0; v < sphere.positions.size(); ++v) {
        if (sphere.positions[v].z > sphere.positions[front].z) front = v;
        if (sphere.positions[v].z < sphere.positions[back].z) back = v;
    }
    EXPECT_FALSE(scene.occluded(view, sphere.positions[front], PointOn::at_vertex(front)));
    EXPECT_TRUE(scene.occluded(view, sphere.positions[back], PointOn::at_vertex(back)));
    EXPECT_GT(scene.tolerance(), 0.0);
    EXPECT_LT(scene.tolerance(), 1e-3);
}

TEST(Visibility, DegenerateAndOutOfRangeTrianglesNeverOcclude) {
    // A big zero-area triangle and one with an out-of-range index between the eye and a point.
    Mesh m;
    m.positions = {{-5, 0, 1}, {5, 0, 1}, {0, 0, 1}, {-5, -5, 1}, {5, -5, 1}};
    m.triangles = {{0, 1, 2}, {3, 4, 77}};
    const RayScene scene(m);
    const Camera camera = camera_at({0.0f, 0.0f, 5.0f}, {0, 1, 0});
    const ImageProjection view(camera, kWidth, kHeight);
    EXPECT_FALSE(scene.occluded(view, {0.0f, -0.0f, -1.0f}));
    EXPECT_FALSE(scene.occluded(view, {0.0f, -2.0f, -1.0f}));
    // A proper triangle does occlude.
    m.triangles.push_back({0, 4, 1});
    const RayScene with_wall(m);
    EXPECT_TRUE(with_wall.occluded(view, {0.0f, -2.0f, -1.0f}));
}

TEST(Visibility, EdgeNeighboursCrossManifoldEdgesAroundTheChosenVertices) {
    // A fan of four triangles around vertex 0 (one with an index out of range) and, apart, three
    // faces on the edge (5, 7) plus one on (6, 7) that touches no chosen vertex.
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0},
                   {5, 5, 0}, {6, 5, 0}, {5, 6, 0}, {6, 6, 0}, {5, 5, 1}};
    m.triangles = {{0, 1, 2}, {5, 6, 7}, {0, 2, 3}, {0, 3, 4}, {0, 4, 99}, {0, 4, 1}, {6, 8, 7}, {5, 7, 9}, {7, 5, 8}};
    const EdgeNeighbours around(m, {3, 0, 3, 42, 5});  // duplicates and an out-of-range vertex
    EXPECT_EQ(around.across(0, 0, 2), 2u);  // fan: face 0 and face 2 share edge (0, 2)
    EXPECT_EQ(around.across(2, 2, 0), 0u);  // either order of the edge's vertices
    EXPECT_EQ(around.across(5, 0, 1), 0u);
    EXPECT_EQ(around.across(3, 0, 4), 5u);  // face 4 has an index out of range: not a neighbour
    EXPECT_EQ(around.across(0, 1, 2), kNoFace);  // a border
    EXPECT_EQ(around.across(1, 5, 7), kNoFace);  // three faces on (5, 7): no one neighbour
    EXPECT_EQ(around.across(1, 6, 7), kNoFace);  // (6, 7) touches no chosen vertex: not covered
    EXPECT_EQ(around.across(0, 0, 0), kNoFace);
    EXPECT_EQ(EdgeNeighbours().across(0, 0, 2), kNoFace);
}

TEST(Visibility, SharedAndCopiedVertexBuffersGiveTheSameAnswers) {
    // RayScene shares the positions with Embree when they have spare capacity (MeshLineData
    // reserves it), else copies them: both must see the same surface.
    Mesh copied = builtin::torus();
    copied.positions.shrink_to_fit();
    Mesh shared = copied;
    shared.positions.reserve(shared.positions.size() + 1);
    ASSERT_EQ(copied.positions.capacity(), copied.positions.size());
    const RayScene a(copied), b(shared);
    const Camera camera = camera_at({0.3f, -3.0f, 1.5f}, {0, 0, 1});
    const ImageProjection view(camera, kWidth, kHeight);
    int hidden = 0;
    for (uint32_t v = 0; v < copied.positions.size(); v += 7) {
        const bool ha = a.occluded(view, copied.positions[v], PointOn::at_vertex(v));
        EXPECT_EQ(ha, b.occluded(view, shared.positions[v], PointOn::at_vertex(v))) << "vertex " << v;
        hidden += ha;
    }
    EXPECT_GT(hidden, 10);  // both sides of the question were asked
    EXPECT_LT(hidden, int(copied.positions.size() / 7) - 10);
}

// A sphere (radius 0.45) in front of the builtin torus (around z, R = 1, r = 0.4), seen from
// above: lines across it at several depths are hidden by up to four surfaces.
Mesh sphere_in_front_of_torus() {
    Mesh m = builtin::torus();
    Mesh ball = builtin::sphere(48, 96, 0.45f);
    const uint32_t base = uint32_t(m.positions.size());
    for (const glm::vec3& p : ball.positions) m.positions.push_back(p + glm::vec3(0.6f, 0.2f, 1.0f));
    for (const glm::uvec3& t : ball.triangles) m.triangles.push_back(t + glm::uvec3(base));
    m.normals = angle_weighted_vertex_normals(m);
    return m;
}

// Straight lines on no face (node keys of vertices the mesh does not have), each a chain of
// segments under a pixel long, across the scene at heights from in front of the sphere to
// behind the torus: through the sphere, between it and the torus, and below the torus (none
// grazes the torus, where a change of level could be thinner than the sampling).
std::vector<LineSegment> lines_across(const ImageProjection& view) {
    std::vector<LineSegment> out;
    uint32_t key = 1000000;
    for (const float z : {1.6f, 1.0f, 0.5f, -0.5f, -1.0f})
        for (float y = -1.3f; y <= 1.31f; y += 0.1f) {
            const glm::vec3 a(-1.6f, y, z), b(1.6f, y, z);
            const glm::dvec3 pa = view.project(a), pb = view.project(b);
            const int n = int(std::ceil(std::hypot(pa.x - pb.x, pa.y - pb.y) / 0.7));
            for (int k = 0; k < n; ++k) {
                LineSegment s;
                s.a = a + (b - a) * (float(k) / float(n));
                s.b = a + (b - a) * (float(k + 1) / float(n));
                s.edge_a = edge_key(key + k, key + k + 5000000);
                s.edge_b = edge_key(key + k + 1, key + k + 5000001);
                out.push_back(s);
            }
            key += uint32_t(n) + 1;
        }
    return out;
}

VisibilitySplit split_on_threads(size_t threads, const RayScene& scene, const Mesh& mesh, const ImageProjection& view,
                                 const std::vector<LineSegment>& segments, const VisibilityOptions& options) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return split_by_visibility(scene, mesh, view, segments, options);
}

bool same_parts(const std::vector<LineSegment>& x, const std::vector<LineSegment>& y) {
    if (x.size() != y.size()) return false;
    for (size_t i = 0; i < x.size(); ++i)
        if (x[i].a != y[i].a || x[i].b != y[i].b || x[i].edge_a != y[i].edge_a || x[i].edge_b != y[i].edge_b)
            return false;
    return true;
}

TEST(Visibility, StreamedLevelsMatchOneRayPerSample) {
    // split_by_visibility traces its samples in streams (rtcOccluded1M, one ray at a time
    // inside Embree, in fixed blocks): a stream must count what a lone ray (rtcOccluded1)
    // towards each of its points counts, the parts the split returns must have the level a lone
    // ray gives in their middle, and one or two threads must give the same parts.
    const Mesh mesh = sphere_in_front_of_torus();
    const Camera camera = camera_at({0.4f, -1.5f, 5.0f}, {0, 1, 0});
    const ImageProjection view(camera, kWidth, kHeight);
    const RayScene scene(mesh);
    const std::vector<LineSegment> lines = lines_across(view);
    VisibilityOptions options;
    options.count_levels_to = 5;
    auto lone_level = [&](const glm::vec3& p) {
        OcclusionQuery q;
        q.point = p;
        uint8_t level = 0;
        scene.occlusion_levels(view, &q, 1, &level, options.count_levels_to);
        return level;
    };

    std::vector<OcclusionQuery> queries;
    for (const LineSegment& s : lines)
        for (const float t : {0.0f, 0.5f}) queries.push_back({.point = s.a + t * (s.b - s.a)});
    std::vector<uint8_t> streamed(queries.size());
    scene.occlusion_levels(view, queries.data(), queries.size(), streamed.data(), options.count_levels_to);
    size_t differ = 0;
    int seen[6] = {};
    for (size_t i = 0; i < queries.size(); ++i) {
        differ += streamed[i] != lone_level(queries[i].point);
        ++seen[std::min<int>(streamed[i], 5)];
    }
    EXPECT_EQ(differ, 0u) << "of " << queries.size() << " points";
    for (const int level : {0, 1, 2, 4}) EXPECT_GT(seen[level], 100) << "points at level " << level;

    const VisibilitySplit split = split_on_threads(1, scene, mesh, view, lines, options);
    const VisibilitySplit split2 = split_on_threads(2, scene, mesh, view, lines, options);
    EXPECT_TRUE(same_parts(split.visible, split2.visible));
    EXPECT_TRUE(same_parts(split.hidden, split2.hidden));
    EXPECT_EQ(split.hidden_levels, split2.hidden_levels);
    // Per line (by its height y, z), its parts along x with their levels: the middle of each
    // part more than a pixel from a change of level along its line must have the level a lone
    // ray gives (nearer a change, a sliver under the 1 px sampling may lie).
    std::map<std::pair<float, float>, std::vector<std::tuple<float, float, uint8_t>>> along;
    auto add = [&](const LineSegment& part, uint8_t level) {
        along[{part.a.y, part.a.z}].push_back({part.a.x, part.b.x, level});
    };
    for (const LineSegment& part : split.visible) add(part, 0);
    for (size_t i = 0; i < split.hidden.size(); ++i) add(split.hidden[i], split.hidden_levels[i]);
    size_t checked = 0, disagree = 0;
    for (auto& [yz, parts] : along) {
        std::sort(parts.begin(), parts.end());
        std::vector<float> changes;
        for (size_t i = 1; i < parts.size(); ++i)
            if (std::get<2>(parts[i]) != std::get<2>(parts[i - 1])) changes.push_back(std::get<0>(parts[i]));
        for (const auto& [x0, x1, level] : parts) {
            const glm::vec3 mid(0.5f * (x0 + x1), yz.first, yz.second);
            bool near_change = false;
            for (const float x : changes)
                near_change = near_change ||
                              glm::length(glm::dvec2(view.project(mid) - view.project({x, yz.first, yz.second}))) < 1.0;
            if (near_change) continue;
            ++checked;
            disagree += lone_level(mid) != level;
        }
    }
    EXPECT_GT(checked, 300u);
    EXPECT_EQ(disagree, 0u) << "of " << checked << " parts";

    // The torus's and sphere's contours (fold walks, own-surface hits): the same on both counts.
    const std::vector<LineSegment> contours = extract_contours(mesh, mesh.normals, camera);
    options.contour = true;
    const VisibilitySplit c1 = split_on_threads(1, scene, mesh, view, contours, options);
    const VisibilitySplit c2 = split_on_threads(2, scene, mesh, view, contours, options);
    EXPECT_FALSE(c1.hidden.empty());
    EXPECT_TRUE(same_parts(c1.visible, c2.visible));
    EXPECT_TRUE(same_parts(c1.hidden, c2.hidden));
    EXPECT_EQ(c1.hidden_levels, c2.hidden_levels);
}

}  // namespace
}  // namespace inkshade::geometry
