#include "geometry/apparent_ridges.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "geometry/analytic_meshes.hpp"
#include "geometry/builtin_models.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {
namespace {

constexpr double kPi = std::numbers::pi;

// The ellipsoid x²/a² + y²/b² + z²/c² = 1 with poles on axis `pole` (0 x, 1 y, 2 z): `slices`
// around, `stacks` bands from pole to pole (odd, so the plane through the equator runs through
// the middle of a band and no vertex lies on it), analytic normals, counter-clockwise seen from
// outside. The poles' fans of slivers give poor curvature estimates, so the tests keep them away
// from where they look.
Mesh ellipsoid(glm::dvec3 axes, int slices, int stacks, int pole = 2) {
    // Local (u, v, w), w along the pole axis, to world: a cyclic permutation (keeps the winding).
    const auto world = [&](const glm::dvec3& l) {
        glm::dvec3 p;
        p[(pole + 1) % 3] = l.x;
        p[(pole + 2) % 3] = l.y;
        p[pole] = l.z;
        return p;
    };
    Mesh m;
    const auto add = [&](const glm::dvec3& local_unit) {
        const glm::dvec3 p = axes * world(local_unit);
        m.positions.push_back(glm::vec3(p));
        m.normals.push_back(glm::vec3(glm::normalize(p / (axes * axes))));
    };
    add({0.0, 0.0, 1.0});
    for (int j = 1; j < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            const double theta = kPi * j / stacks, phi = 2.0 * kPi * i / slices;
            add({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
        }
    const uint32_t south = uint32_t(m.positions.size());
    add({0.0, 0.0, -1.0});
    const auto ring = [&](int j, int i) { return uint32_t(1 + (j - 1) * slices + (i % slices)); };
    for (int i = 0; i < slices; ++i) {
        m.triangles.emplace_back(0u, ring(1, i), ring(1, i + 1));
        m.triangles.emplace_back(south, ring(stacks - 1, i + 1), ring(stacks - 1, i));
    }
    for (int j = 1; j + 1 < stacks; ++j)
        for (int i = 0; i < slices; ++i) {
            m.triangles.emplace_back(ring(j, i), ring(j + 1, i), ring(j + 1, i + 1));
            m.triangles.emplace_back(ring(j, i), ring(j + 1, i + 1), ring(j, i + 1));
        }
    return m;
}

Camera orthographic_from(const glm::vec3& eye, const glm::vec3& up) {
    Camera c;
    c.eye = eye;
    c.target = glm::vec3(0.0f);
    c.up = up;
    c.orthographic = true;
    c.ortho_height = 3.5f;
    c.near_plane = 0.5f;
    c.far_plane = 20.0f;
    return c;
}

// The view-dependent curvature of the ellipsoid evaluated from its equation, independently of
// the mesh: a point of the image (X, Y) in the basis (s1, s2) of the image plane is lifted to
// the front of the surface, and the normal's derivative with respect to (X, Y) is taken in
// closed form (n = g / |g|, g = D p, D = diag(1/a², 1/b², 1/c²); the surface point moves along
// the tangent vector δ − (δ·n / d·n) d for an image displacement δ, d the unit view vector).
struct AnalyticEllipsoid {
    glm::dvec3 axes, d, s1, s2;

    glm::dvec3 D() const { return 1.0 / (axes * axes); }
    std::optional<glm::dvec3> lift(double X, double Y) const {
        const glm::dvec3 o = X * s1 + Y * s2, w = D();
        const double A = glm::dot(w, d * d), B = 2.0 * glm::dot(w, d * o), C = glm::dot(w, o * o) - 1.0;
        const double disc = B * B - 4.0 * A * C;
        if (disc <= 0.0) return std::nullopt;
        return o + (-B + std::sqrt(disc)) / (2.0 * A) * d;
    }
    // q1 and its image direction (in (s1, s2) coordinates) at image point (X, Y).
    std::optional<std::pair<double, glm::dvec2>> q1(double X, double Y) const {
        const auto p = lift(X, Y);
        if (!p) return std::nullopt;
        const glm::dvec3 g = D() * *p, n = glm::normalize(g);
        glm::dvec3 col[2];
        for (int k = 0; k < 2; ++k) {
            const glm::dvec3 s = k == 0 ? s1 : s2;
            const glm::dvec3 t = s - glm::dot(s, n) / glm::dot(d, n) * d;
            const glm::dvec3 dg = D() * t;
            col[k] = (dg - glm::dot(n, dg) * n) / glm::length(g);
        }
        const double a = glm::dot(col[0], col[0]), b = glm::dot(col[0], col[1]), c = glm::dot(col[1], col[1]);
        const double lambda = 0.5 * (a + c) + std::sqrt(0.25 * (a - c) * (a - c) + b * b);
        glm::dvec2 e(b, lambda - a);
        if (glm::length(glm::dvec2(lambda - c, b)) > glm::length(e)) e = glm::dvec2(lambda - c, b);
        e = glm::length(e) > 1e-12 ? glm::normalize(e) : glm::dvec2(1.0, 0.0);
        return std::pair{std::sqrt(lambda), e};
    }
    // D_t1 q1 at (X, Y) by central differences of q1 along t1 (step h in the image).
    double dt1_q1(double X, double Y, const glm::dvec2& t, double h) const {
        const auto plus = q1(X + h * t.x, Y + h * t.y), minus = q1(X - h * t.x, Y - h * t.y);
        return (plus->first - minus->first) / (2.0 * h);
    }
    glm::dvec2 image(const glm::dvec3& p) const { return {glm::dot(p, s1), glm::dot(p, s2)}; }
};

// The elongated ellipsoid seen end-on along its long axis x (orthographic): by the symmetry
// z → −z, D_t1 q1 = 0 on the plane z = 0 wherever t1 is the image's z direction, and there q1
// is a maximum (the 2D section x²/a² + z²/c² = 1 seen along a has projected curvature
// (a/c²) / (√(1 − s²) (1 + (a²/c² − 1) s²)), s = z/c, which falls away from s = 0 when
// a²/c² > 3/2). Across the image that ridge runs from the tip out to |y| ≈ 0.94 b, where t1
// turns towards y (from the analytic evaluation below).
const glm::dvec3 kAxes(1.5, 1.0, 0.6);
constexpr float kFeatureSize = 0.2f;  // threshold 0.1 / 0.04: q1 > 1.58 (q1 = a/c² = 4.2 at the tip)

TEST(ApparentRidges, EllipsoidSeenEndOnHasItsRidgeOnTheMiddlePlane) {
    const Mesh m = ellipsoid(kAxes, 256, 129);
    const Curvature k = compute_curvature(m, m.normals);
    const Camera camera = orthographic_from({6.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f});
    const ApparentRidgeOptions options{.threshold = 0.1f, .feature_size = kFeatureSize};
    const auto segs = extract_apparent_ridges(m, m.normals, k, camera, options);
    ASSERT_FALSE(segs.empty());

    const AnalyticEllipsoid e{kAxes, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double band = kPi * kAxes.z / 129.0;  // the mesh's band height at the equator
    std::vector<double> covered(20, 0.0);       // length drawn per 0.1 of y in [−1, 1]
    double left = 0.0, right = 0.0;
    for (const LineSegment& s : segs) {
        for (const glm::vec3& p : {s.a, s.b}) {
            // Away from the outline (|n·v| > 0.2) and from the ridge's ends (|y| > 0.9, where t1
            // turns and the line curls off) every point lies on z = 0 ...
            const glm::dvec3 n = glm::normalize(glm::dvec3(p) / (kAxes * kAxes));
            if (n.x < 0.2 || std::abs(p.y) > 0.9f) continue;
            EXPECT_LT(std::abs(p.z), 0.5 * band) << "at y = " << p.y;
            // ... where the analytic q1 passes the threshold and has a maximum along t1: D_t1 q1
            // is near zero against its values a few bands either side, positive before, negative
            // after.
            const auto q = e.q1(p.y, p.z);
            ASSERT_TRUE(q);
            EXPECT_GT(q->first * q->first, 0.1 / (kFeatureSize * kFeatureSize)) << "at y = " << p.y;
            EXPECT_GT(std::abs(q->second.y), 0.99) << "t1 is the image's z direction at y = " << p.y;
            const double h = 4.0 * band;
            const glm::dvec2 t = q->second.y > 0.0 ? q->second : -q->second;
            const double here = e.dt1_q1(p.y, p.z, t, 0.25 * band);
            const double before = e.dt1_q1(p.y - h * t.x, p.z - h * t.y, t, 0.25 * band);
            const double after = e.dt1_q1(p.y + h * t.x, p.z + h * t.y, t, 0.25 * band);
            EXPECT_GT(before, 0.0);
            EXPECT_LT(after, 0.0);
            EXPECT_LT(std::abs(here), 0.2 * std::min(before, -after)) << "at y = " << p.y;
        }
        const glm::vec3 mid = 0.5f * (s.a + s.b);
        const double length = glm::distance(s.a, s.b);
        if (std::abs(mid.y) < 0.8f) (mid.y < 0.0f ? left : right) += length;
        const int bin = std::clamp(int(std::floor((mid.y + 1.0f) * 10.0f)), 0, 19);
        if (std::abs(mid.z) < 0.5 * band) covered[size_t(bin)] += length;
    }
    // The ridge runs unbroken across the middle 1.6 b of the image, the same length each side.
    for (int bin = 2; bin < 18; ++bin) EXPECT_GT(covered[size_t(bin)], 0.09) << "y bin " << bin;
    EXPECT_NEAR(left, right, 0.02 * (left + right));
    // The strength is rtsc's fade 1 − threshold / q1², from the analytic q1 at the tip.
    const double q_tip = kAxes.x / (kAxes.z * kAxes.z);
    for (const LineSegment& s : segs) {
        if (std::abs(s.a.y) < 0.01f && std::abs(s.a.z) < 0.5 * band) {
            EXPECT_NEAR(s.strength_a, 1.0 - 0.1 / (kFeatureSize * kFeatureSize) / (q_tip * q_tip), 0.03);
        }
    }

    // A threshold above the ridge's q1 (q1 = 4.2 at the tip, 0.1 / 0.05² = 40 > 4.2²) removes it
    // from the middle of the image.
    const auto high = extract_apparent_ridges(m, m.normals, k, camera, {.threshold = 0.1f, .feature_size = 0.05f});
    for (const LineSegment& s : high) {
        if (glm::normalize(glm::dvec3(s.a) / (kAxes * kAxes)).x > 0.2) {
            EXPECT_GT(std::abs(s.a.y), 0.3f);
        }
    }
}

// Seen along its short axis z, the same ellipsoid has D_t1 q1 = 0 on the plane y = 0 too, but as
// a minimum of q1 (q1 grows towards the outline in every direction): no apparent ridge inside,
// only at the outline, where q1 ~ 1 / |n·v| peaks (rtsc's test of the field's direction at the
// corners tells the two apart).
TEST(ApparentRidges, EllipsoidSeenAlongItsShortAxisHasMinimaOnlyInside) {
    const Mesh m = ellipsoid(kAxes, 256, 129, /*pole=*/0);
    const Curvature k = compute_curvature(m, m.normals);
    const Camera camera = orthographic_from({0.0f, 0.0f, 6.0f}, {0.0f, 1.0f, 0.0f});
    // No threshold: q1 = c/b² = 0.6 at the top is below any useful one, and the test is about
    // telling maxima from minima.
    const auto segs =
        extract_apparent_ridges(m, m.normals, k, camera, {.threshold = 0.0f, .feature_size = kFeatureSize});
    ASSERT_FALSE(segs.empty()) << "the outline";
    for (const LineSegment& s : segs)
        for (const glm::vec3& p : {s.a, s.b}) {
            const glm::dvec3 n = glm::normalize(glm::dvec3(p) / (kAxes * kAxes));
            EXPECT_LT(std::abs(n.z), 0.1) << "inside, at " << p.x << ", " << p.y << ", " << p.z;
        }
}

// A cylinder seen from the side: q1 = 1 / (r cos φ) along the circumference (φ from the view
// direction, the axis direction has none), rising monotonically to the outline, so the only
// apparent ridges are at the two outlines; a sphere likewise (q1 = 1 / (r cos θ)).
TEST(ApparentRidges, CylinderAndSphereHaveThemOnlyAtTheirOutlines) {
    const Mesh cyl = test::cylinder(1.0f, 256, 60, 4.0f);
    const Curvature kc = compute_curvature(cyl, cyl.normals);
    const Camera side = orthographic_from({6.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 1.0f});
    const auto segs = extract_apparent_ridges(cyl, cyl.normals, kc, side, {.threshold = 0.1f, .feature_size = 0.1f});
    ASSERT_FALSE(segs.empty());
    double near_outline = 0.0;
    for (const LineSegment& s : segs)
        for (const glm::vec3& p : {s.a, s.b}) {
            if (p.z < 0.1f || p.z > 3.9f) continue;  // the open ends
            // Within two faces (2 · 2π/256) of the outline y = ±1.
            EXPECT_LT(std::abs(p.x), 2.0 * 2.0 * kPi / 256.0) << "at " << p.x << ", " << p.y << ", " << p.z;
            near_outline += 0.5 * glm::distance(s.a, s.b);
        }
    EXPECT_GT(near_outline, 2.0 * 3.0) << "both outlines, most of their length";

    const Mesh sphere = builtin::sphere();
    const Curvature ks = compute_curvature(sphere, sphere.normals);
    const auto on_sphere = extract_apparent_ridges(sphere, sphere.normals, ks, side, {.feature_size = 0.1f});
    const glm::vec3 view = glm::normalize(side.eye);
    for (const LineSegment& s : on_sphere)
        for (const glm::vec3& p : {s.a, s.b}) EXPECT_LT(std::abs(glm::dot(p, view)), 0.1f) << p.y << ", " << p.z;
}

// Through the line extractor: the ridge of the end-on ellipsoid behind a plate covering y > 0
// is drawn only where nothing hides it, and as a hidden layer behind the plate.
TEST(ApparentRidges, HiddenPartBehindAnOccluderIsDropped) {
    Mesh m = ellipsoid(kAxes, 256, 129);
    const uint32_t base = uint32_t(m.positions.size());
    // A plate at x = 2 (between the ellipsoid and the eye) over 0.1 < y < 2, |z| < 1, facing +x.
    for (const glm::vec3 p : {glm::vec3(2, 0.1f, -1), glm::vec3(2, 2, -1), glm::vec3(2, 2, 1), glm::vec3(2, 0.1f, 1)}) {
        m.positions.push_back(p);
        m.normals.push_back({1, 0, 0});
    }
    m.triangles.emplace_back(base, base + 1, base + 2);
    m.triangles.emplace_back(base, base + 2, base + 3);
    LineExtractor extractor(m);
    const Camera camera = orthographic_from({6.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f});
    const LineDrawing d = extractor.draw(
        camera, 400, 400,
        {{"apparent-ridge", {{"feature-size", {kFeatureSize}}, {"hidden", {1.0f}}, {"max-level", {0.0f}}}}});
    ASSERT_EQ(d.layers.size(), 1u);
    // Seen from +x with z up, image x grows with y: the plate covers image x > 200 + 0.1 / 3.5 · 400.
    const float plate_edge = 200.0f + 0.1f / 3.5f * 400.0f;
    double visible_left = 0.0, hidden_right = 0.0;
    for (const LinePath& path : d.layers[0].visible)
        for (size_t i = 0; i + 1 < path.points.size(); ++i) {
            const glm::vec2 a = path.points[i], b = path.points[i + 1];
            EXPECT_LT(std::max(a.x, b.x), plate_edge + 1.0f) << "a visible piece behind the plate";
            if (std::abs(a.y - 200.0f) < 2.0f) visible_left += glm::distance(a, b);
        }
    for (const LinePath& path : d.layers[0].hidden) {
        EXPECT_GE(path.level, 1);
        for (size_t i = 0; i + 1 < path.points.size(); ++i)
            if (std::abs(path.points[i].y - 200.0f) < 2.0f && path.points[i].x > plate_edge)
                hidden_right += glm::distance(path.points[i], path.points[i + 1]);
    }
    // The middle 0.8 b of each half: 0.8 / 3.5 · 400 ≈ 91 px.
    EXPECT_GT(visible_left, 80.0);
    EXPECT_GT(hidden_right, 70.0);
}

TEST(ApparentRidges, BadInputsGiveNoCrashAndSizeMismatchThrows) {
    Mesh m = ellipsoid(kAxes, 16, 9);
    const Curvature k = compute_curvature(m, m.normals);
    const Camera camera = orthographic_from({6.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f});
    EXPECT_THROW(extract_apparent_ridges(m, {}, k, camera), std::invalid_argument);
    EXPECT_THROW(extract_apparent_ridges(m, m.normals, Curvature{}, camera), std::invalid_argument);
    EXPECT_TRUE(extract_apparent_ridges(Mesh{}, {}, Curvature{}, camera).empty());
    // A NaN normal, a repeated and an out-of-range index: finite lines elsewhere, no crash.
    Curvature bad = k;
    bad.k1[3] = std::nanf("");
    m.triangles.emplace_back(0u, 0u, 1u);
    m.triangles.emplace_back(0u, 1u, 100000u);
    for (const LineSegment& s : extract_apparent_ridges(m, m.normals, bad, camera, {.threshold = 0.0f}))
        for (const glm::vec3& p : {s.a, s.b}) EXPECT_TRUE(std::isfinite(p.x + p.y + p.z));
}

}  // namespace
}  // namespace inkshade::geometry
