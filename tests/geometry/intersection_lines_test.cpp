#include "geometry/intersection_lines.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/analytic_meshes.hpp"
#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"
#include "geometry/visibility.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {
namespace {

// Appends `part` scaled then moved by `offset` (indices shifted): one mesh of several parts.
void append(Mesh& mesh, const Mesh& part, glm::vec3 offset, glm::vec3 scale = glm::vec3(1.0f)) {
    const uint32_t base = uint32_t(mesh.positions.size());
    for (const glm::vec3& p : part.positions) mesh.positions.push_back(p * scale + offset);
    for (const glm::uvec3& t : part.triangles) mesh.triangles.push_back(t + glm::uvec3(base));
}

Mesh two_spheres(int rings, int segments) {
    const Mesh sphere = builtin::sphere(rings, segments, 1.0f);
    Mesh m;
    append(m, sphere, {-0.5f, 0.0f, 0.0f});
    append(m, sphere, {0.5f, 0.0f, 0.0f});
    return m;
}

// How far the tessellated unit sphere lies inside the sphere: 1 − the least distance of a
// face's plane from the centre (a face lies between its plane and the sphere).
double sphere_chord_error(int rings, int segments) {
    const Mesh s = builtin::sphere(rings, segments, 1.0f);
    double worst = 0.0;
    for (const glm::uvec3& t : s.triangles) {
        const glm::dvec3 a(s.positions[t.x]), b(s.positions[t.y]), c(s.positions[t.z]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) == 0.0) continue;
        worst = std::max(worst, 1.0 - std::abs(glm::dot(glm::normalize(n), a)));
    }
    return worst;
}

// The spheres of radius 1 at (±0.5, 0, 0) meet on the circle x = 0, y² + z² = 0.75.
const double kCircleRadius = std::sqrt(0.75);

double distance_to_circle(const glm::vec3& p) {
    return std::hypot(double(p.x), std::hypot(double(p.y), double(p.z)) - kCircleRadius);
}

bool is_pierce_key(uint64_t key) { return uint32_t(key >> 32) == 0xfffffffcu; }

void expect_well_formed(const std::vector<LineSegment>& segments) {
    for (size_t i = 0; i < segments.size(); ++i) {
        const LineSegment& s = segments[i];
        EXPECT_NE(s.edge_a, s.edge_b) << i;
        EXPECT_TRUE(is_pierce_key(s.edge_a) && is_pierce_key(s.edge_b)) << i;
        EXPECT_LT(s.face, s.face_b) << i;
        EXPECT_EQ(s.strength_a, 1.0f);
        EXPECT_EQ(s.strength_b, 1.0f);
        if (i > 0) {
            const LineSegment& r = segments[i - 1];
            EXPECT_TRUE(r.face < s.face || (r.face == s.face && r.face_b < s.face_b)) << "sorted by (face, face_b)";
        }
    }
}

TEST(IntersectionLines, TwoSpheresMeetOnTheirAnalyticCircleInOneLoop) {
    const int rings = 32, segments = 64;
    const Mesh m = two_spheres(rings, segments);
    const std::vector<LineSegment> lines = extract_intersections(m);
    ASSERT_FALSE(lines.empty());
    expect_well_formed(lines);
    const uint32_t first_of_second = uint32_t(m.triangles.size() / 2);
    // Both faces lie within δ inside their spheres: then |x| ≤ δ and the radius in the yz
    // plane is at least sqrt(0.75 − 2δ), so a point is within about 1.5δ of the circle.
    const double delta = sphere_chord_error(rings, segments);
    const double bound = 2.0 * delta + 1e-6;
    EXPECT_LT(bound, 1e-2);
    double worst = 0.0;
    for (const LineSegment& s : lines) {
        EXPECT_LT(s.face, first_of_second);
        EXPECT_GE(s.face_b, first_of_second);
        worst = std::max({worst, distance_to_circle(s.a), distance_to_circle(s.b)});
    }
    EXPECT_LT(worst, bound) << "chord error " << delta;

    const std::vector<Polyline> chains = chain_segments(lines);
    ASSERT_EQ(chains.size(), 1u);
    EXPECT_TRUE(chains[0].closed);
    EXPECT_EQ(chains[0].points.size(), lines.size());
    const double length = 2.0 * std::numbers::pi * kCircleRadius;
    EXPECT_NEAR(polyline_length(chains[0]), length, 0.01 * length);
}

TEST(IntersectionLines, SurfacesThatDoNotCrossHaveNone) {
    EXPECT_TRUE(extract_intersections(builtin::sphere()).empty());
    EXPECT_TRUE(extract_intersections(builtin::torus()).empty());
    EXPECT_TRUE(extract_intersections(builtin::torus_knot()).empty());
    EXPECT_TRUE(extract_intersections(test::cube()).empty());
    EXPECT_TRUE(extract_intersections(Mesh{}).empty());
    // Two spheres apart, and one inside the other: no surface crosses another.
    Mesh apart, nested;
    append(apart, builtin::sphere(16, 32), {-1.5f, 0.0f, 0.0f});
    append(apart, builtin::sphere(16, 32), {1.5f, 0.0f, 0.0f});
    append(nested, builtin::sphere(16, 32), glm::vec3(0.0f));
    append(nested, builtin::sphere(16, 32), glm::vec3(0.1f), glm::vec3(0.5f));
    EXPECT_TRUE(extract_intersections(apart).empty());
    EXPECT_TRUE(extract_intersections(nested).empty());
}

// A 2×2×2 box and a 1×1×2 bar standing in it up to z = 2: they cross on the unit square
// max(|x − cx|, |y − cy|) = 0.5 of the box's top face z = 1.
void expect_square_at_top(glm::vec2 centre) {
    Mesh m;
    append(m, test::cube(1.0f), glm::vec3(0.0f));
    append(m, test::cube(1.0f), glm::vec3(centre, 1.0f), glm::vec3(0.5f, 0.5f, 1.0f));
    const std::vector<LineSegment> lines = extract_intersections(m);
    expect_well_formed(lines);
    for (const LineSegment& s : lines)
        for (const glm::vec3& p : {s.a, s.b}) {
            EXPECT_NEAR(p.z, 1.0f, 1e-6f);
            EXPECT_NEAR(std::max(std::abs(p.x - centre.x), std::abs(p.y - centre.y)), 0.5f, 1e-6f);
        }
    const std::vector<Polyline> chains = chain_segments(lines);
    ASSERT_EQ(chains.size(), 1u) << "centre " << centre.x << ", " << centre.y;
    EXPECT_TRUE(chains[0].closed);
    EXPECT_NEAR(polyline_length(chains[0]), 4.0f, 1e-5f);
    // The four corners are on the loop (there the bar's vertical edges pierce the top).
    for (const glm::vec2 corner :
         {glm::vec2(-0.5f, -0.5f), glm::vec2(0.5f, -0.5f), glm::vec2(0.5f, 0.5f), glm::vec2(-0.5f, 0.5f)}) {
        const glm::vec3 c(centre + corner, 1.0f);
        double nearest = 1e9;
        for (const glm::vec3& p : chains[0].points) nearest = std::min(nearest, double(glm::length(p - c)));
        EXPECT_LT(nearest, 1e-6) << corner.x << ", " << corner.y;
    }
}

TEST(IntersectionLines, CrossingBoxesMeetOnARectangle) {
    // Centred, the top face's diagonal runs exactly through two of the bar's vertical edges:
    // a crossing through an edge, which the fixed sign rule gives to one of the two faces.
    expect_square_at_top({0.0f, 0.0f});
    expect_square_at_top({0.2f, -0.15f});
    expect_square_at_top({0.25f, 0.25f});  // all four bar edges off the diagonal
}

// A strip of width 2w along the curve (s² − 1, 0, s³ − s), s in [−1.5, 1.5], which passes the
// origin twice (s = ±1) in directions (∓2, 0, 2): the two halves of one mesh cross along the
// y axis, y in [−w, w].
Mesh folded_strip(float w, int steps) {
    Mesh m;
    for (int k = 0; k <= steps; ++k) {
        const double s = -1.5 + 3.0 * k / steps;
        const glm::vec3 c(float(s * s - 1.0), 0.0f, float(s * s * s - s));
        m.positions.push_back(c + glm::vec3(0.0f, -w, 0.0f));
        m.positions.push_back(c + glm::vec3(0.0f, w, 0.0f));
    }
    for (uint32_t k = 0; k < uint32_t(steps); ++k) {
        const uint32_t a = 2 * k, b = 2 * k + 1, c = 2 * k + 2, d = 2 * k + 3;
        m.triangles.emplace_back(a, c, d);
        m.triangles.emplace_back(a, d, b);
    }
    return m;
}

TEST(IntersectionLines, SelfIntersectingStripHasItsLine) {
    const float w = 0.3f;
    const Mesh m = folded_strip(w, 61);  // no cross-section at s = ±1
    const std::vector<LineSegment> lines = extract_intersections(m);
    ASSERT_FALSE(lines.empty());
    expect_well_formed(lines);
    // Each quad of the strip is a flat rectangle, so the line is straight along y where the
    // two chords cross, within the chord error of the curve there.
    for (const LineSegment& s : lines)
        for (const glm::vec3& p : {s.a, s.b}) {
            EXPECT_LT(std::abs(p.x), 1e-2f);
            EXPECT_LT(std::abs(p.z), 1e-2f);
            EXPECT_LE(std::abs(p.y), w + 1e-6f);
        }
    const std::vector<Polyline> chains = chain_segments(lines);
    ASSERT_EQ(chains.size(), 1u);
    EXPECT_FALSE(chains[0].closed);
    EXPECT_NEAR(polyline_length(chains[0]), 2.0f * w, 1e-5f);
    EXPECT_NEAR(std::abs(chains[0].points.front().y - chains[0].points.back().y), 2.0f * w, 1e-5f);
}

TEST(IntersectionLines, TeapotSpoutAndHandleCrossItsBody) {
    // Newell's patches overlap where the spout and the handle join the body: a closed loop
    // around the spout's root (x ≈ 1.9), one around the handle's upper root (x ≈ −1.6, y > 2),
    // and a piece at its lower root, whose open end pokes out of the body.
    const std::vector<LineSegment> lines = extract_intersections(builtin::teapot(16));
    expect_well_formed(lines);
    int spout = 0, handle = 0;
    for (const Polyline& line : chain_segments(lines)) {
        glm::vec3 lo(1e9f), hi(-1e9f);
        for (const glm::vec3& p : line.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
        if (line.closed && lo.x > 1.8f && hi.x < 2.0f) ++spout;
        if (line.closed && lo.x > -1.75f && hi.x < -1.5f && lo.y > 2.0f) ++handle;
    }
    EXPECT_EQ(spout, 1);
    EXPECT_EQ(handle, 1);
}

// Triangle A in z = 0 and triangle B through it, from (ax, ay, 0) to below and above.
Mesh crossing_pair(bool share_index, glm::vec3 b0) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5f, 0.5f, -1.0f}, {0.2f, 0.2f, 1.0f}, b0};
    m.triangles = {{0, 1, 2}, {share_index ? 0u : 5u, 3, 4}};
    return m;
}

TEST(IntersectionLines, PairsSharingAVertexAreSkipped) {
    // B runs from A's corner through A's inside: they cross along a segment from the corner,
    // but share a vertex — as in Line Art, no line.
    EXPECT_TRUE(extract_intersections(crossing_pair(true, {0, 0, 0})).empty());
    // Moved off the corner (outside A), B crosses A: one segment, from A's corner (in B's
    // plane x = y, inside B) to where B's edge opposite the moved vertex pierces A.
    std::vector<LineSegment> lines = extract_intersections(crossing_pair(false, {-0.1f, -0.1f, 0.0f}));
    ASSERT_EQ(lines.size(), 1u);
    expect_well_formed(lines);
    EXPECT_EQ(lines[0].face, 0u);
    EXPECT_EQ(lines[0].face_b, 1u);
    const bool a_at_corner = lines[0].a == glm::vec3(0.0f);
    EXPECT_TRUE(a_at_corner || lines[0].b == glm::vec3(0.0f));
    EXPECT_LT(glm::length((a_at_corner ? lines[0].b : lines[0].a) - glm::vec3(0.35f, 0.35f, 0.0f)), 1e-6f);
    // Two parts with a vertex each at the same point (not shared: separate indices) meet
    // there: the segment runs from that point.
    lines = extract_intersections(crossing_pair(false, {0, 0, 0}));
    ASSERT_EQ(lines.size(), 1u);
    expect_well_formed(lines);
    const glm::vec3 ends[2] = {lines[0].a, lines[0].b};
    EXPECT_TRUE(ends[0] == glm::vec3(0.0f) || ends[1] == glm::vec3(0.0f));
    const glm::vec3 far = ends[0] == glm::vec3(0.0f) ? ends[1] : ends[0];
    EXPECT_LT(glm::length(far - glm::vec3(0.35f, 0.35f, 0.0f)), 1e-6f);
}

TEST(IntersectionLines, DegenerateContactsAndBrokenFacesAreSafe) {
    const glm::vec3 nan(std::numeric_limits<float>::quiet_NaN());
    Mesh m;
    // Face 0: a big triangle in z = 0.
    m.positions = {{-2, -2, 0}, {2, -2, 0}, {0, 2, 0}};
    m.triangles = {{0, 1, 2}};
    const auto add = [&](std::vector<glm::vec3> p) {
        const uint32_t base = uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(), p.begin(), p.end());
        m.triangles.emplace_back(base, base + 1, base + 2);
    };
    add({{-0.5f, 0, 0}, {0.5f, 0, 0}, {0, 0.5f, 0}});           // 1: coplanar, overlapping: none
    add({{-0.5f, 0.2f, 0}, {0.5f, 0.2f, 0}, {0, 0.2f, 1}});     // 2: an edge lying on face 0, above it
    add({{0, -0.5f, 0}, {0.3f, -0.5f, 1}, {-0.3f, -0.5f, 1}});  // 3: a vertex touching face 0 from above
    add({{0, 0.8f, 0}, {0.3f, 0.8f, 1}, {-0.3f, 0.9f, -1}});    // 4: through face 0 at a vertex of its own
    add({{1, 1, 1}, {1, 1, 1}, {2, 2, 2}});                     // 5: zero area
    add({nan, {0, 0, -1}, {0, 0, 1}});                          // 6: not finite
    m.triangles.emplace_back(0, 1, 99);                         // 7: out of range
    m.triangles.emplace_back(3, 3, 4);                          // 8: repeated index
    const std::vector<LineSegment> lines = extract_intersections(m);
    expect_well_formed(lines);
    for (const LineSegment& s : lines) {
        EXPECT_TRUE(s.face <= 4 && s.face_b <= 4) << s.face << " " << s.face_b;
        EXPECT_NE(s.face_b, 1u) << "coplanar";
        EXPECT_NE(s.face_b, 3u) << "touching at a vertex";
        EXPECT_TRUE(std::isfinite(s.a.x) && std::isfinite(s.b.x));
    }
    // Face 4 crosses face 0 from its vertex (0, 0.8, 0), which is an end of the segment.
    const auto four = std::find_if(lines.begin(), lines.end(), [](const LineSegment& s) { return s.face_b == 4; });
    ASSERT_NE(four, lines.end());
    EXPECT_TRUE(four->a == glm::vec3(0, 0.8f, 0) || four->b == glm::vec3(0, 0.8f, 0));

    // Coordinates near the float range (their sums overflow a float) still give a finite line.
    Mesh huge;
    huge.positions = {{-3e38f, -3e38f, 0}, {3e38f, -3e38f, 0}, {0, 3e38f, 0}, {0, 0, -1}, {1, 0, 1}, {0, 1, 1}};
    huge.triangles = {{0, 1, 2}, {3, 4, 5}};
    const std::vector<LineSegment> one = extract_intersections(huge);
    ASSERT_EQ(one.size(), 1u);
    expect_well_formed(one);
    EXPECT_NEAR(one[0].a.z, 0.0f, 1e-6f);
    EXPECT_NEAR(one[0].b.z, 0.0f, 1e-6f);
}

TEST(IntersectionLines, ResultDoesNotDependOnThreadCount) {
    Mesh m = two_spheres(64, 128);
    append(m, folded_strip(0.3f, 61), {0.0f, 0.0f, 0.5f});
    std::vector<LineSegment> one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = extract_intersections(m);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = extract_intersections(m);
    }
    ASSERT_FALSE(one.empty());
    ASSERT_EQ(one.size(), two.size());
    for (size_t i = 0; i < one.size(); ++i) {
        EXPECT_EQ(one[i].a, two[i].a);
        EXPECT_EQ(one[i].b, two[i].b);
        EXPECT_EQ(one[i].edge_a, two[i].edge_a);
        EXPECT_EQ(one[i].edge_b, two[i].edge_b);
        EXPECT_EQ(one[i].face, two[i].face);
        EXPECT_EQ(one[i].face_b, two[i].face_b);
    }
}

// Distance in pixels from p to the polyline through `q` (closed).
double distance_to_loop(const glm::dvec2& p, const std::vector<glm::dvec2>& q) {
    double best = 1e30;
    for (size_t i = 0; i < q.size(); ++i) {
        const glm::dvec2 a = q[i], b = q[(i + 1) % q.size()], ab = b - a;
        const double len2 = glm::dot(ab, ab);
        const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, glm::length(p - (a + t * ab)));
    }
    return best;
}

TEST(IntersectionLines, LineExtractorDrawsTheVisibleHalfOfTheCircle) {
    const int width = 320, height = 240;
    Camera camera;
    camera.eye = {1.0f, 0.8f, 4.0f};  // mostly along −z: the circle's front half faces the eye
    camera.target = glm::vec3(0.0f);
    camera.up = {0.0f, 1.0f, 0.0f};
    camera.fov_degrees = 35.0f;
    camera.near_plane = 0.5f;
    camera.far_plane = 20.0f;
    LineExtractor extractor(two_spheres(64, 128));
    std::vector<LineTiming> timings;
    const LineDrawing drawing = extractor.draw(camera, width, height, {{"intersection", {}}}, &timings);
    ASSERT_EQ(drawing.layers.size(), 1u);
    const LineLayer& layer = drawing.layers[0];
    ASSERT_FALSE(layer.visible.empty());
    EXPECT_TRUE(std::any_of(timings.begin(), timings.end(), [](const LineTiming& t) {
        return t.stage == "intersections";
    })) << "computed once per mesh, timed on its own";

    const ImageProjection view(camera, width, height);
    std::vector<glm::dvec2> circle;
    for (int i = 0; i < 8192; ++i) {
        const double a = 2.0 * std::numbers::pi * i / 8192;
        const glm::dvec3 p = view.project(glm::vec3(0.0, kCircleRadius * std::cos(a), kCircleRadius * std::sin(a)));
        circle.emplace_back(p.x, p.y);
    }
    size_t points = 0;
    double worst = 0.0;
    for (const LinePath& path : layer.visible)
        for (const glm::vec2& p : path.points) {
            worst = std::max(worst, distance_to_loop(glm::dvec2(p), circle));
            ++points;
        }
    EXPECT_LT(worst, 1.0);
    EXPECT_GT(points, 20u);

    // A second view reuses the cached lines.
    extractor.draw(camera, width, height, {{"intersection", {}}}, &timings);
    EXPECT_TRUE(
        std::none_of(timings.begin(), timings.end(), [](const LineTiming& t) { return t.stage == "intersections"; }));
}

TEST(IntersectionLines, IsARegisteredObjectSpaceType) {
    const LineType& type = line_type("intersection");
    EXPECT_EQ(type.space, LineSpace::Object);
    EXPECT_FLOAT_EQ(line_param({"intersection", {}}, "width").at(0), 1.0f);
    EXPECT_FLOAT_EQ(line_param({"intersection", {}}, "min-length").at(0), 0.0f);
}

}  // namespace
}  // namespace inkshade::geometry
