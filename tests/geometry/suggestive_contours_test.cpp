#include "geometry/suggestive_contours.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

#include "geometry/analytic_meshes.hpp"
#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"
#include "geometry/feature_size.hpp"
#include "geometry/normals.hpp"

namespace inkshade::geometry {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kImage = 512.0f;  // test image size in pixels

// Pixel coordinates of p in a kImage² image (origin at the centre).
glm::vec2 project(const Camera& camera, const glm::vec3& p) {
    const glm::vec4 clip = camera.projection(1.0f) * camera.view() * glm::vec4(p, 1.0f);
    return glm::vec2(clip) / clip.w * (0.5f * kImage);
}

Camera ortho_camera(const glm::vec3& eye, const glm::vec3& target = glm::vec3(0.0f), float height = 2.6f) {
    Camera c;
    c.eye = eye;
    c.target = target;
    c.orthographic = true;
    c.ortho_height = height;
    return c;
}

Camera perspective_camera(const glm::vec3& eye, const glm::vec3& target = glm::vec3(0.0f)) {
    Camera c;
    c.eye = eye;
    c.target = target;
    c.fov_degrees = 40.0f;
    return c;
}

// Height field z = A sin(k x) over [−1.2, 1.2] × [−0.5, 0.5], `nx` × `ny` quads, analytic normals.
struct Wave {
    float k = 2.0f * kPi;  // one period per unit of x: inflections at x = n/2
    float A = 0.5f / k;    // steepest slope A k = 0.5 (26.6°)
    Mesh mesh(int nx = 240, int ny = 50) const {
        Mesh m;
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) {
                const float x = -1.2f + 2.4f * float(i) / float(nx), y = -0.5f + float(j) / float(ny);
                m.positions.emplace_back(x, y, A * std::sin(k * x));
                m.normals.push_back(glm::normalize(glm::vec3(-A * k * std::cos(k * x), 0.0f, 1.0f)));
            }
        const auto idx = [&](int i, int j) { return uint32_t(j * (nx + 1) + i); };
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                m.triangles.emplace_back(idx(i, j), idx(i + 1, j), idx(i + 1, j + 1));
                m.triangles.emplace_back(idx(i, j), idx(i + 1, j + 1), idx(i, j + 1));
            }
        return m;
    }
};

using test::cylinder;

std::vector<LineSegment> suggestive(const Mesh& m, const Camera& camera, const SuggestiveOptions& options = {}) {
    return extract_suggestive_contours(m, m.normals, compute_curvature(m, m.normals), camera, options);
}

// Suggestive contours of z = A sin(kx) seen from a view tilted by β about y, towards +x. Along
// x (a principal direction; the other curvature is 0) κr = κ = A k² sin(kx) / (1 + z'²)^{3/2},
// zero at the inflections x = nπ/k. There w points along +x times v·t with v·t ∝ sin β + z' cos β,
// and dκ/ds = A k³ cos(kx) / (1 + z'²)², so sign(D_w κr) = sign((−1)ⁿ sin β + A k cos β). With
// A k = 0.5 and β = ±45° the factor is ±0.71 + 0.35: only even n qualify for β > 0 (surface
// turned away from the eye, n·v minimal along w), only odd n for β < 0.
TEST(SuggestiveContours, WaveLinesLieOnTheQualifyingInflectionsOnly) {
    const Wave wave;
    const Mesh m = wave.mesh();
    const Curvature curvature = compute_curvature(m, m.normals);
    for (const float beta_deg : {45.0f, -45.0f}) {
        const float beta = glm::radians(beta_deg);
        const Camera camera = ortho_camera(5.0f * glm::vec3(std::sin(beta), 0.0f, std::cos(beta)));
        const auto segs = extract_suggestive_contours(m, m.normals, curvature, camera);
        ASSERT_FALSE(segs.empty()) << beta_deg;
        const int parity = beta_deg > 0 ? 0 : 1;  // which inflections n qualify (n mod 2)
        std::map<int, double> length;             // per qualifying inflection, inside the margin
        for (const LineSegment& s : segs) {
            EXPECT_GE(s.strength_a, 0.0f);
            EXPECT_LE(s.strength_a, 1.0f);
            EXPECT_GE(s.strength_b, 0.0f);
            EXPECT_LE(s.strength_b, 1.0f);
            // Away from the mesh border (where one-sided curvature estimates are rough).
            const glm::vec3 mid = 0.5f * (s.a + s.b);
            if (std::abs(mid.x) > 1.1f || std::abs(mid.y) > 0.4f) continue;
            const int n = int(std::lround(2.0f * mid.x));  // nearest inflection x = n/2
            EXPECT_EQ(((n % 2) + 2) % 2, parity) << "line near x = " << mid.x << ", beta " << beta_deg;
            for (const glm::vec3& p : {s.a, s.b}) {
                // Within one pixel of the projected inflection line x = n/2, z = 0.
                const glm::vec2 q = project(camera, p);
                const glm::vec2 l0 = project(camera, {0.5f * float(n), -1.0f, 0.0f});
                const glm::vec2 l1 = project(camera, {0.5f * float(n), 1.0f, 0.0f});
                const glm::vec2 d = glm::normalize(l1 - l0);
                const glm::vec2 r = q - l0;
                EXPECT_LT(std::abs(r.x * d.y - r.y * d.x), 1.0f) << "x " << p.x << " beta " << beta_deg;
            }
            length[n] += glm::distance(s.a, s.b);
        }
        // Each qualifying inflection inside the margin is drawn across the whole band |y| < 0.4.
        const std::vector<int> expected = parity == 0 ? std::vector<int>{-2, 0, 2} : std::vector<int>{-1, 1};
        for (const int n : expected) EXPECT_GT(length[n], 0.75) << "inflection " << n << " beta " << beta_deg;
    }
}

// The gently curved height field z = 0.2 sin(3x), x in [−π, π], y in [−1, 1], 400 × 100 cells,
// seen from straight above: by the analysis above (β = 0, A k = 0.6) every inflection x = nπ/3
// qualifies, where the normal leans 31° from the view, so D_w κr / (n·v) = A k³ tan 31° / (1 +
// 0.36)² ≈ 1.75. With default parameters they are drawn: the automatic feature size is rtsc's
// (|k2| = 0 makes the 10th percentile 0, so 5 % of the bounding sphere's radius, 0.165, and the
// trim threshold 0.01 / 0.165² = 0.37), where 1 % of the bounding-box diagonal (0.07, threshold
// 2.0) trimmed every one.
TEST(SuggestiveContours, GentleHeightFieldHasThemWithDefaultParameters) {
    const int nx = 400, ny = 100;
    Mesh m;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const float x = -kPi + 2.0f * kPi * float(i) / float(nx), y = -1.0f + 2.0f * float(j) / float(ny);
            m.positions.emplace_back(x, y, 0.2f * std::sin(3.0f * x));
            m.normals.push_back(glm::normalize(glm::vec3(-0.6f * std::cos(3.0f * x), 0.0f, 1.0f)));
        }
    test::add_grid_triangles(m, nx, ny);
    const Curvature curvature = compute_curvature(m, m.normals);
    const float radius = bounding_sphere_radius(m);
    EXPECT_NEAR(radius, std::sqrt(kPi * kPi + 1.0f + 0.04f), 0.05f);
    EXPECT_FLOAT_EQ(line_feature_size(m, curvature), 0.05f * radius);

    const Camera camera = ortho_camera({0.0f, 0.0f, 8.0f}, glm::vec3(0.0f), 7.0f);
    std::map<int, double> length;  // per inflection, away from the border
    for (const LineSegment& s : extract_suggestive_contours(m, m.normals, curvature, camera)) {
        const glm::vec3 mid = 0.5f * (s.a + s.b);
        if (std::abs(mid.x) > 2.9f || std::abs(mid.y) > 0.9f) continue;
        const int n = int(std::lround(3.0f * mid.x / kPi));
        for (const glm::vec3& p : {s.a, s.b})
            EXPECT_LT(std::abs(project(camera, p).x - project(camera, {float(n) * kPi / 3.0f, p.y, 0.0f}).x), 1.0f)
                << "x " << p.x;
        length[n] += glm::distance(s.a, s.b);
    }
    for (const int n : {-2, -1, 0, 1, 2}) EXPECT_GT(length[n], 1.6) << "inflection " << n;  // across |y| < 0.9

    // The old automatic size, 1 % of the bounding-box diagonal, trims them all.
    SuggestiveOptions old;
    old.feature_size = 0.01f * m.bounds().diagonal();
    EXPECT_TRUE(extract_suggestive_contours(m, m.normals, curvature, camera, old).empty());
}

TEST(FeatureSize, IsRtscsFromTheCurvature) {
    // A sphere of radius 2: |k1| = |k2| = 1/2 everywhere, so 1 % of 2 = 0.02 (below the cap, 5 %
    // of the radius); scaling the sphere scales it.
    for (const float r : {2.0f, 0.5f}) {
        Mesh m = builtin::sphere(64, 128, r);
        const Curvature k = compute_curvature(m, m.normals);
        EXPECT_NEAR(bounding_sphere_radius(m), r, 1e-3f * r);
        EXPECT_NEAR(line_feature_size(m, k), 0.01f * r, 5e-4f * r) << r;
    }
    // A flat square: every curvature 0, so the cap, 5 % of its bounding sphere's radius.
    Mesh flat;
    for (int j = 0; j <= 10; ++j)
        for (int i = 0; i <= 10; ++i) flat.positions.emplace_back(0.1f * float(i), 0.1f * float(j), 0.0f);
    flat.normals.assign(flat.positions.size(), glm::vec3(0, 0, 1));
    test::add_grid_triangles(flat, 10, 10);
    EXPECT_NEAR(line_feature_size(flat, compute_curvature(flat, flat.normals)), 0.05f * std::sqrt(0.5f), 1e-4f);
    // Nothing to measure: 1.
    EXPECT_EQ(line_feature_size(Mesh{}, Curvature{}), 1.0f);
}

TEST(SuggestiveContours, WaveLinesChainIntoOnePolylinePerInflection) {
    const Mesh m = Wave{}.mesh();
    const Camera camera = ortho_camera(5.0f * glm::normalize(glm::vec3(1, 0, 1)));
    const auto lines = drop_short(chain_segments(suggestive(m, camera)), 0.2f);
    int long_lines = 0;
    for (const Polyline& l : lines) {
        ASSERT_EQ(l.strength.size(), l.points.size());
        if (polyline_length(l) > 0.8f) ++long_lines;
    }
    EXPECT_EQ(long_lines, 3);  // x = −1, 0, 1, each across the strip
}

TEST(SuggestiveContours, NoneOnSphere) {
    const Mesh m = builtin::sphere(128, 256, 1.0f);
    const Curvature curvature = compute_curvature(m, m.normals);
    for (const Camera& camera : {ortho_camera({0, 0, 5}), ortho_camera({1.5f, 2.0f, 4.0f}),
                                 perspective_camera({1, 2, 3}), perspective_camera({0, 0, 2.5f})})
        EXPECT_TRUE(extract_suggestive_contours(m, m.normals, curvature, camera).empty());
}

TEST(SuggestiveContours, NoneOnCylinderWhereRadialCurvatureTouchesZero) {
    // κr = cos²φ / r ≥ 0, zero along the line facing the viewer. Radial noise of ±0.01 % (as
    // a scanner leaves) makes the estimated κr change sign there; the D_w κr trim must reject
    // those zeros.
    Mesh m = cylinder(1.0f, 128, 60, 4.0f);
    for (size_t v = 0; v < m.positions.size(); ++v) {
        uint32_t h = uint32_t(v) * 2654435761u;
        h ^= h >> 15;
        h *= 2246822519u;
        h ^= h >> 13;
        const float noise = (float(h & 0xffffu) / 65535.0f - 0.5f) * 2.0f;  // [-1, 1]
        m.positions[v] += 1e-4f * noise * m.normals[v];
    }
    m.normals = angle_weighted_vertex_normals(m);
    const Curvature curvature = compute_curvature(m, m.normals);
    const glm::vec3 centre(0, 0, 2);
    size_t untrimmed = 0;
    for (const Camera& camera : {ortho_camera({5, 0, 2}, centre, 5.0f), ortho_camera({3, 2, 5}, centre, 5.0f),
                                 perspective_camera({4, 1, 2}, centre), perspective_camera({2, -3, 6}, centre)}) {
        const auto segs = extract_suggestive_contours(m, m.normals, curvature, camera);
        EXPECT_TRUE(segs.empty()) << segs.size() << " segments, eye " << camera.eye.x << "," << camera.eye.y << ","
                                  << camera.eye.z;
        // The noisy zero crossings are there: only the trim removes them.
        untrimmed +=
            extract_suggestive_contours(m, m.normals, curvature, camera, {.threshold = -1e6f, .fade = 0.0f}).size();
    }
    EXPECT_GT(untrimmed, 10u);
}

// A view from 27° above the torus's equatorial plane: the inner contour ends inside the hole and
// suggestive contours continue it over the saddle-shaped inner half (DeCarlo et al. 2003 fig. 2).
const glm::vec3 kTorusEye = 4.0f * glm::normalize(glm::vec3(0.3f, 0.5f, 0.3f));

TEST(SuggestiveContours, TorusLinesLieOnTheInnerHalf) {
    const float R = 1.0f, r = 0.4f;
    const Mesh m = builtin::torus(R, r, 256, 128);
    const Camera camera = perspective_camera(kTorusEye);
    const auto segs = suggestive(m, camera);
    ASSERT_GT(segs.size(), 20u);
    for (const LineSegment& s : segs)
        for (const glm::vec3& p : {s.a, s.b})
            // Outside the axis distance R both principal curvatures are positive: κr > 0.
            EXPECT_LT(std::hypot(p.x, p.y), R + 1e-3f);
    const auto lines = drop_short(chain_segments(segs), 0.1f);
    EXPECT_FALSE(lines.empty());
}

TEST(SuggestiveContours, NeighbouringSegmentsShareEndpointsAndStrengths) {
    const Mesh m = builtin::torus(1.0f, 0.4f, 256, 128);
    const auto segs = suggestive(m, perspective_camera(kTorusEye));
    ASSERT_FALSE(segs.empty());
    std::map<uint64_t, std::pair<glm::vec3, float>> at;
    size_t shared = 0;
    for (const LineSegment& s : segs) {
        EXPECT_NE(s.edge_a, s.edge_b);
        for (const auto& [key, p, w] :
             {std::tuple{s.edge_a, s.a, s.strength_a}, std::tuple{s.edge_b, s.b, s.strength_b}}) {
            const auto [it, inserted] = at.emplace(key, std::pair{p, w});
            if (!inserted) {
                ++shared;
                EXPECT_EQ(it->second.first, p);  // bit-identical
                EXPECT_EQ(it->second.second, w);
            }
        }
    }
    EXPECT_GT(shared, segs.size() / 2);
}

TEST(SuggestiveContours, ThresholdTrimsAndFadeSetsStrength) {
    const Mesh m = builtin::torus(1.0f, 0.4f, 128, 64);
    const Curvature c = compute_curvature(m, m.normals);
    const Camera camera = perspective_camera(kTorusEye);
    const auto total = [](const std::vector<LineSegment>& segs) {
        double sum = 0.0;
        for (const LineSegment& s : segs) sum += glm::distance(s.a, s.b);
        return sum;
    };
    const auto loose = extract_suggestive_contours(m, m.normals, c, camera, {.threshold = 0.0f});
    const auto normal = extract_suggestive_contours(m, m.normals, c, camera);
    const auto strict = extract_suggestive_contours(m, m.normals, c, camera, {.threshold = 0.03f});
    EXPECT_GT(total(loose), total(normal));
    EXPECT_GT(total(normal), total(strict));
    // A trimmed end has an interior key and strength 0 where the test cut it, or 1 where it
    // runs into the contour (n·v = 0); without fading all strengths are 1.
    size_t faded = 0;
    for (const LineSegment& s : normal)
        for (const auto& [key, strength, end] :
             {std::tuple{s.edge_a, s.strength_a, 0u}, std::tuple{s.edge_b, s.strength_b, 1u}}) {
            if (key != face_interior_key(s.face, end)) continue;
            EXPECT_TRUE(strength < 1e-3f || strength == 1.0f) << strength;
            faded += strength < 1e-3f;
        }
    EXPECT_GT(faded, 0u);
    for (const LineSegment& s : extract_suggestive_contours(m, m.normals, c, camera, {.fade = 0.0f})) {
        EXPECT_EQ(s.strength_a, 1.0f);
        EXPECT_EQ(s.strength_b, 1.0f);
    }
}

TEST(SuggestiveContours, RadialCurvatureMatchesCylinderAndSphere) {
    const Mesh cyl = cylinder(0.5f, 128, 30, 2.0f);
    const Curvature cc = compute_curvature(cyl, cyl.normals);
    const Camera camera = ortho_camera({3, 1, 4}, {0, 0, 1});
    const glm::vec3 v = glm::normalize(camera.eye - camera.target);
    const RadialCurvature rc = radial_curvature(cyl, cyl.normals, cc, camera);
    ASSERT_EQ(rc.kr.size(), cyl.vertex_count());
    for (size_t i = 0; i < cyl.vertex_count(); ++i) {
        const float z = cyl.positions[i].z;
        if (z < 0.1f || z > 1.9f) continue;  // border rows
        const glm::vec3 n = cyl.normals[i];
        const glm::vec3 w = v - glm::dot(v, n) * n;
        const glm::vec3 around(-n.y, n.x, 0.0f);
        const float cos_phi = glm::dot(w, around) / glm::length(w);
        EXPECT_NEAR(rc.kr[i], cos_phi * cos_phi / 0.5f, 0.02f) << i;
        EXPECT_NEAR(rc.ndotv[i], glm::dot(n, v), 1e-5f);
    }
    const Mesh sphere = builtin::sphere(64, 128, 2.0f);
    const RadialCurvature rs = radial_curvature(sphere, sphere.normals, compute_curvature(sphere, sphere.normals),
                                                perspective_camera({1, 2, 6}));
    for (size_t i = 0; i < sphere.vertex_count(); ++i) {
        EXPECT_NEAR(rs.kr[i], 0.5f, 0.01f) << i;
        EXPECT_NEAR(rs.dw_kr[i], 0.0f, 0.01f) << i;
    }
}

// D_w κr against a central difference of the analytic κr of the torus along w, at the vertices
// where κr ≈ 0 (where the trim uses it). The −2 (n·v) τr² term is about a third of the value
// there, so dropping or flipping it fails this test.
TEST(SuggestiveContours, DerivativeMatchesAnalyticTorusAtZeros) {
    const double R = 1.0, r = 0.4;
    const Mesh m = builtin::torus(float(R), float(r), 256, 128);
    const Camera camera = ortho_camera(kTorusEye);
    const glm::dvec3 v = glm::normalize(glm::dvec3(camera.eye));
    // Unit tangents along the ring (angle t) and around the tube (angle a).
    const auto frame = [](double t, double a) {
        return std::pair{glm::dvec3(-std::sin(t), std::cos(t), 0.0),
                         glm::dvec3(-std::sin(a) * std::cos(t), -std::sin(a) * std::sin(t), std::cos(a))};
    };
    const auto kr = [&](double t, double a) {  // curvatures cos a / (R + r cos a) and 1 / r
        const auto [et, ea] = frame(t, a);
        const double x = glm::dot(v, et), y = glm::dot(v, ea);
        return (std::cos(a) / (R + r * std::cos(a)) * x * x + y * y / r) / (x * x + y * y);
    };
    const RadialCurvature rc = radial_curvature(m, m.normals, compute_curvature(m, m.normals), camera);
    int checked = 0;
    for (size_t i = 0; i < m.vertex_count(); ++i) {
        if (std::abs(rc.kr[i]) > 0.02f || rc.ndotv[i] < 0.2f) continue;
        const glm::dvec3 p(m.positions[i]);
        const double t = std::atan2(p.y, p.x), a = std::atan2(p.z, std::hypot(p.x, p.y) - R);
        const auto [et, ea] = frame(t, a);
        const double x = glm::dot(v, et), y = glm::dot(v, ea), w = std::hypot(x, y);
        const double h = 1e-5;
        const double d_t = (kr(t + h, a) - kr(t - h, a)) / (2.0 * h) / (R + r * std::cos(a));
        const double d_a = (kr(t, a + h) - kr(t, a - h)) / (2.0 * h) / r;
        const double expected = w * ((x / w) * d_t + (y / w) * d_a);  // |w| times d/ds along ŵ
        EXPECT_NEAR(rc.dw_kr[i], expected, 0.03) << i;
        ++checked;
    }
    EXPECT_GT(checked, 50);
}

// ---- suggestive highlights: the zeros of κr where D_w κr < 0 ---------------------------------

// The wave of WaveLinesLieOnTheQualifyingInflectionsOnly at β = ±60°: sign(D_w κr) =
// sign((−1)ⁿ sin β + A k cos β) = sign(±0.87 + 0.25), so suggestive highlights lie on the
// inflections the suggestive contours skip — odd n for β > 0, even n for β < 0. There the
// normal leans 33° from v and −D_w κr / (n·v) = tan 33° · A k³ / 1.25² = 8.3, above the
// default trim 0.02 / 0.065² = 4.7 (at β = 45° it would be 4.2, trimmed).
TEST(SuggestiveHighlights, WaveLinesLieOnTheInflectionsSuggestiveContoursSkip) {
    const Wave wave;
    const Mesh m = wave.mesh();
    const Curvature curvature = compute_curvature(m, m.normals);
    for (const float beta_deg : {60.0f, -60.0f}) {
        const float beta = glm::radians(beta_deg);
        const Camera camera = ortho_camera(5.0f * glm::vec3(std::sin(beta), 0.0f, std::cos(beta)));
        const auto segs =
            extract_suggestive_contours(m, m.normals, curvature, camera, {.threshold = 0.02f, .highlights = true});
        ASSERT_FALSE(segs.empty()) << beta_deg;
        const int parity = beta_deg > 0 ? 1 : 0;
        std::map<int, double> length;
        for (const LineSegment& s : segs) {
            const glm::vec3 mid = 0.5f * (s.a + s.b);
            if (std::abs(mid.x) > 1.1f || std::abs(mid.y) > 0.4f) continue;
            const int n = int(std::lround(2.0f * mid.x));
            EXPECT_EQ(((n % 2) + 2) % 2, parity) << "line near x = " << mid.x << ", beta " << beta_deg;
            for (const glm::vec3& p : {s.a, s.b}) EXPECT_NEAR(p.x, 0.5f * float(n), 3e-3f);
            length[n] += glm::distance(s.a, s.b);
        }
        const std::vector<int> expected = parity == 0 ? std::vector<int>{-2, 0, 2} : std::vector<int>{-1, 1};
        EXPECT_EQ(length.size(), expected.size());
        for (const int n : expected) EXPECT_GT(length[n], 0.75) << "inflection " << n << " beta " << beta_deg;
    }
}

// At every point of the torus's suggestive highlights the analytic κr vanishes and falls along
// w (its central difference along w on the analytic torus), where at the suggestive contours'
// points it rises: the two are the halves of κr = 0 split by the sign of D_w κr.
TEST(SuggestiveHighlights, TorusPointsHaveRadialCurvatureZeroAndFallingAlongW) {
    const double R = 1.0, r = 0.4;
    const Mesh m = builtin::torus(float(R), float(r), 256, 128);
    const Camera camera = ortho_camera(kTorusEye);
    const glm::dvec3 v = glm::normalize(glm::dvec3(camera.eye));
    const auto frame = [](double t, double a) {
        return std::pair{glm::dvec3(-std::sin(t), std::cos(t), 0.0),
                         glm::dvec3(-std::sin(a) * std::cos(t), -std::sin(a) * std::sin(t), std::cos(a))};
    };
    const auto kr = [&](double t, double a) {
        const auto [et, ea] = frame(t, a);
        const double x = glm::dot(v, et), y = glm::dot(v, ea);
        return (std::cos(a) / (R + r * std::cos(a)) * x * x + y * y / r) / (x * x + y * y);
    };
    // κr at p and its derivative along w (per unit length of the unit vector ŵ).
    const auto analytic = [&](const glm::vec3& p) {
        const double t = std::atan2(p.y, p.x), a = std::atan2(p.z, std::hypot(p.x, p.y) - R);
        const auto [et, ea] = frame(t, a);
        const double x = glm::dot(v, et), y = glm::dot(v, ea), w = std::hypot(x, y), h = 1e-5;
        const double d_t = (kr(t + h, a) - kr(t - h, a)) / (2.0 * h) / (R + r * std::cos(a));
        const double d_a = (kr(t, a + h) - kr(t, a - h)) / (2.0 * h) / r;
        return std::pair{kr(t, a), (x / w) * d_t + (y / w) * d_a};
    };
    const Curvature c = compute_curvature(m, m.normals);
    for (const bool highlights : {true, false}) {
        const auto segs = extract_suggestive_contours(
            m, m.normals, c, camera, {.threshold = highlights ? 0.02f : 0.01f, .highlights = highlights});
        ASSERT_GT(segs.size(), 20u) << highlights;
        for (const LineSegment& s : segs)
            for (const glm::vec3& p : {s.a, s.b}) {
                const auto [k, dk] = analytic(p);
                EXPECT_NEAR(k, 0.0, 0.03) << "highlights " << highlights;
                EXPECT_LT(highlights ? dk : -dk, 0.0)
                    << "highlights " << highlights << " at " << p.x << "," << p.y << "," << p.z;
            }
    }
}

TEST(SuggestiveContours, BadMeshesGiveResultsWithoutCrashing) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0.3f}, {0.5f, -1, 0.2f}, {0.5f, 0, 1},
                   {2, 2, 2}, {0, 0, 0}, {NAN, 0, 0},     {9, 9, 9}};
    m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {1, 1, 2}, {0, 1, 99}, {2, 4, 6}, {0, 6, 2}, {3, 4, 7}};
    m.normals = angle_weighted_vertex_normals(m);
    const Curvature c = compute_curvature(m, m.normals);
    for (const Camera& camera :
         {ortho_camera({0, 0, 5}), perspective_camera({1, 2, 3}), perspective_camera({0, 0, 0})}) {  // eye on a vertex
        const auto segs = extract_suggestive_contours(m, m.normals, c, camera, {.threshold = -1e6f});
        for (const LineSegment& s : segs) {
            EXPECT_NE(s.edge_a, s.edge_b);
            EXPECT_TRUE(std::isfinite(s.strength_a) && std::isfinite(s.strength_b));
        }
        (void)chain_segments(segs);
        const RadialCurvature rc = radial_curvature(m, m.normals, c, camera);
        for (const float k : rc.kr) EXPECT_TRUE(std::isfinite(k));
    }
    EXPECT_THROW(extract_suggestive_contours(m, {}, c, ortho_camera({0, 0, 5})), std::invalid_argument);
    EXPECT_THROW(radial_curvature(m, m.normals, Curvature{}, ortho_camera({0, 0, 5})), std::invalid_argument);
    EXPECT_TRUE(suggestive(Mesh{}, ortho_camera({0, 0, 5})).empty());
}

}  // namespace
}  // namespace inkshade::geometry
