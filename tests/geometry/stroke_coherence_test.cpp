#include "geometry/stroke_coherence.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/builtin_models.hpp"
#include "geometry/dash_pattern.hpp"
#include "geometry/path_arc_length.hpp"
#include "geometry/stroke_drift.hpp"
#include "geometry/stroke_style.hpp"
#include "stroke_paths.hpp"

namespace inkshade::geometry {
namespace {

using test::circle_path;
using test::straight_path;

// u = offset + arc length on every point.
void set_u(LinePath& p, float offset) {
    const std::vector<double> s = arc_lengths(p);
    p.u.resize(p.points.size());
    for (size_t i = 0; i < p.points.size(); ++i) p.u[i] = float(offset + s[i]);
}

// Float storage: u is exact to a few ulps of its size.
constexpr double kUlpTolerance = 1e-6;
double tolerance(double u) { return kUlpTolerance * std::max(1.0, std::abs(u)) * 4.0; }

TEST(StrokeCoherence, ShiftedCopyTakesTheShiftedParameter) {
    // The previous frame's stroke from x = 10 to 210 with u = 37.25 + s; this frame's is the
    // part from x = 30.5 on, so its u must be 37.25 + 20.5 + s.
    LinePath before = straight_path({10.0f, 50.0f}, {210.0f, 50.0f}, 3.0f);
    set_u(before, 37.25f);
    std::vector<LinePath> now = {straight_path({30.5f, 50.0f}, {180.0f, 50.0f}, 2.5f)};
    parameterise_paths(now, {before}, nullptr);
    ASSERT_EQ(now[0].u.size(), now[0].points.size());
    for (size_t i = 0; i < now[0].points.size(); ++i) {
        const double expected = 37.25 + double(now[0].points[i].x) - 10.0;
        EXPECT_NEAR(now[0].u[i], expected, tolerance(expected)) << i;
    }
}

TEST(StrokeCoherence, ShiftedInTheImageFollowsTheProjection) {
    // The previous stroke's surface points projected into this frame land 3 px lower and 6 px
    // to the right (the model moved): u follows the surface, not the old image position.
    LinePath before = straight_path({10.0f, 50.0f}, {210.0f, 50.0f}, 1.0f);
    for (const glm::vec2& p : before.points) before.world.emplace_back(p.x, p.y, 0.0f);
    set_u(before, 5.0f);
    std::vector<LinePath> now = {straight_path({16.0f, 53.0f}, {216.0f, 53.0f}, 1.0f)};
    parameterise_paths(now, {before}, [](const glm::vec3& w) { return glm::vec2(w.x + 6.0f, w.y + 3.0f); });
    ASSERT_FALSE(now[0].u.empty());
    EXPECT_NEAR(now[0].u.front(), 5.0, 1e-4);
    EXPECT_NEAR(now[0].u.back(), 205.0, 1e-4);
}

TEST(StrokeCoherence, ReversedStrokeIsTurnedRound) {
    // The chain runs the other way this frame: it is reversed so u still increases along it
    // and every point keeps the u of the same place.
    LinePath before = straight_path({10.0f, 50.0f}, {210.0f, 50.0f}, 2.0f);
    set_u(before, 0.0f);
    std::vector<LinePath> now = {straight_path({200.0f, 50.0f}, {20.0f, 50.0f}, 2.0f)};
    parameterise_paths(now, {before}, nullptr);
    ASSERT_EQ(now[0].u.size(), now[0].points.size());
    EXPECT_FLOAT_EQ(now[0].points.front().x, 20.0f);
    for (size_t i = 0; i < now[0].points.size(); ++i)
        EXPECT_NEAR(now[0].u[i], double(now[0].points[i].x) - 10.0, 1e-4) << i;
}

TEST(StrokeCoherence, LoopStartsWhereThePreviousLoopStarted) {
    // A circle whose chain started at angle 0 with u = 12; this frame's chain of the same circle
    // starts a quarter turn on. The seam goes back to angle 0 and u to 12 + s there.
    LinePath before = circle_path({160.0f, 120.0f}, 80.0f, 720);
    set_u(before, 12.0f);
    const LinePath turned = rotated(before, 180);
    std::vector<LinePath> now = {turned};
    now[0].u.clear();
    parameterise_paths(now, {before}, nullptr);
    ASSERT_TRUE(now[0].closed);
    ASSERT_EQ(now[0].u.size(), now[0].points.size());
    EXPECT_NEAR(glm::length(now[0].points.front() - before.points.front()), 0.0, 1e-3);
    EXPECT_NEAR(now[0].u.front(), 12.0, 1e-3);
    // Every point has the u of the same place in the previous frame.
    for (size_t i = 0; i < now[0].points.size(); i += 37) {
        const glm::vec2 p = now[0].points[i];
        size_t nearest = 0;
        for (size_t j = 0; j < before.points.size(); ++j)
            if (glm::length(before.points[j] - p) < glm::length(before.points[nearest] - p)) nearest = j;
        EXPECT_NEAR(now[0].u[i], before.u[nearest], 0.5) << i;
    }
}

TEST(StrokeCoherence, NewStrokeWithoutVotesStartsAtZero) {
    LinePath before = straight_path({10.0f, 50.0f}, {210.0f, 50.0f}, 2.0f);
    set_u(before, 100.0f);
    // 40 px away from the old stroke (beyond the search radius), and one across it (directions
    // at 90°): neither takes a vote.
    std::vector<LinePath> now = {straight_path({10.0f, 90.0f}, {110.0f, 90.0f}, 2.0f),
                                 straight_path({100.0f, 0.0f}, {100.0f, 100.0f}, 2.0f)};
    parameterise_paths(now, {before}, nullptr);
    for (const LinePath& p : now) {
        ASSERT_EQ(p.u.size(), p.points.size());
        const std::vector<double> s = arc_lengths(p);
        for (size_t i = 0; i < p.points.size(); ++i) EXPECT_NEAR(p.u[i], s[i], 1e-4) << i;
    }
    // And the first frame: no previous strokes at all.
    std::vector<LinePath> first = {circle_path({50.0f, 50.0f}, 20.0f, 64)};
    parameterise_paths(first, {}, nullptr);
    EXPECT_FLOAT_EQ(first[0].u.front(), 0.0f);
}

TEST(StrokeCoherence, DashesFollowTheParameter) {
    // A dash pattern 10 on, 10 off anchored to u: with u = 5 + s the first dash is the 5 px
    // left of the first period's "on" part, and the dashes start at u = 20 k.
    LinePath p = straight_path({0.0f, 0.0f}, {100.0f, 0.0f}, 1.0f);
    set_u(p, 5.0f);
    const std::vector<LinePath> dashes = dash_paths({p}, {10.0f, 10.0f});
    ASSERT_EQ(dashes.size(), 6u);
    EXPECT_NEAR(dashes.back().points.front().x, 95.0, 1e-4);
    EXPECT_NEAR(dashes.back().points.back().x, 100.0, 1e-4);
    EXPECT_NEAR(dashes[0].points.front().x, 0.0, 1e-4);
    EXPECT_NEAR(dashes[0].points.back().x, 5.0, 1e-4);
    for (size_t k = 1; k < dashes.size(); ++k) {
        EXPECT_NEAR(dashes[k].points.front().x, 20.0 * double(k) - 5.0, 1e-4) << k;
        EXPECT_NEAR(dashes[k].u.front(), 20.0 * double(k), 1e-4) << k;
    }
    // Without u, the pattern starts at the path's start, as before.
    p.u.clear();
    const std::vector<LinePath> plain = dash_paths({p}, {10.0f, 10.0f});
    ASSERT_EQ(plain.size(), 5u);
    EXPECT_NEAR(plain[1].points.front().x, 20.0, 1e-4);
}

TEST(StrokeCoherence, JitterAndNoiseFollowTheParameter) {
    // Two strokes along one line, the second starting 30 px further on and second in the list:
    // with u set, a point at the same u moves by the same jitter and gets the same width noise
    // (the noise is read at u and is the layer's, not the path index's); without u they differ.
    LinePath a = straight_path({0.0f, 50.0f}, {200.0f, 50.0f}, 1.0f);
    LinePath b = straight_path({30.0f, 50.0f}, {200.0f, 50.0f}, 1.0f);
    set_u(a, 0.0f);
    set_u(b, 30.0f);
    StrokeModifiers m;
    m.sketch.jitter_px = 3.0f;
    m.sketch.period_px = 20.0f;
    m.thickness.width = 4.0f;
    m.thickness.noise = 0.5f;
    m.thickness.noise_period_px = 20.0f;
    auto styled = [&](bool with_u) {
        std::vector<LinePath> in = {a, b};
        if (!with_u)
            for (LinePath& p : in) p.u.clear();
        return style_strokes(in, m, ViewDepthRange{}, 7);
    };
    for (const bool with_u : {true, false}) {
        const std::vector<LinePath> out = styled(with_u);
        ASSERT_EQ(out.size(), 2u);
        double worst_offset = 0.0, worst_width = 0.0;
        for (size_t i = 0; i < out[1].points.size(); ++i) {  // b's point i is a's point i + 30
            const glm::vec2 da = out[0].points[i + 30] - a.points[i + 30], db = out[1].points[i] - b.points[i];
            worst_offset = std::max(worst_offset, double(glm::length(da - db)));
            worst_width = std::max(worst_width, double(std::abs(out[0].width[i + 30] - out[1].width[i])));
        }
        if (with_u) {
            EXPECT_LT(worst_offset, 1e-4);
            EXPECT_LT(worst_width, 1e-4);
        } else {
            EXPECT_GT(worst_offset, 0.5);
            EXPECT_GT(worst_width, 0.2);
        }
    }
}

// --- Sequences through the line extractor ---------------------------------------------------

constexpr int kWidth = 320, kHeight = 240;

Camera orbit_camera(double azimuth_degrees, double elevation_degrees, double distance) {
    const double az = glm::radians(azimuth_degrees), el = glm::radians(elevation_degrees);
    Camera c;
    c.eye = glm::vec3(glm::dvec3(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el)) * distance);
    c.target = glm::vec3(0.0f);
    c.up = glm::vec3(0, 1, 0);
    c.fov_degrees = 35.0f;
    c.near_plane = 0.5f;
    c.far_plane = 20.0f;
    return c;
}

// The StrokeSequence after each of `frames` orbit views of `mesh` (azimuth 10° a frame).
// `by`: "surface" or "image" (coherence-by), empty for no coherence.
std::vector<StrokeSequence> orbit(const Mesh& mesh, const std::string& by, int frames, double distance,
                                  double elevation = 20.0) {
    LineExtractor extractor(mesh);
    const LineSettings contour{"contour",
                               {{"coherence", {by.empty() ? 0.0f : 1.0f}},
                                {"coherence-by", {by == "image" ? 1.0f : 0.0f}},
                                {"dash", {12.0f, 8.0f}}}};
    StrokeSequence sequence;
    std::vector<StrokeSequence> out;
    for (int f = 0; f < frames; ++f) {
        extractor.draw(orbit_camera(10.0 * f, elevation, distance), kWidth, kHeight, {contour}, nullptr, &sequence);
        out.push_back(sequence);
    }
    return out;
}

TEST(StrokeCoherenceSequence, SphereOrbitMarksStayPut) {
    // Orbiting a sphere about its centre, the contour is the same circle every frame, so every
    // motion of a mark along it is drift. The chain's start moves with the mesh edges the
    // contour crosses, and so do marks measured from it; coherent marks matched in the image
    // stay put.
    const Mesh sphere = builtin::sphere();
    DriftOptions o;
    o.expect = DriftExpectation::SamePlace;
    const DriftReport plain = measure_drift(orbit(sphere, "", 36, 4.0), o);
    const DriftReport coherent = measure_drift(orbit(sphere, "image", 36, 4.0), o);
    ASSERT_GT(plain.drifts.size(), 500u);
    ASSERT_GT(coherent.drifts.size(), 500u);
    EXPECT_GT(plain.median_px, 5.0) << "the chain start moves";
    EXPECT_GT(plain.p95_px, 20.0);
    EXPECT_LE(coherent.median_px, 0.5);
    EXPECT_LE(coherent.p95_px, 2.0);
    EXPECT_EQ(coherent.lost, 0u);
    EXPECT_EQ(coherent.unmatched, 0u);
    // By the surface, seen from the equator the orbit turns the surface about the image's
    // vertical only and the marks still stay put; from 20° above it, it also turns the image
    // about the centre, by about 10° sin 20° a frame, and marks carried by the surface go round
    // the outline with it (the surface's own motion there, not a parameterisation error).
    const DriftReport level = measure_drift(orbit(sphere, "surface", 36, 4.0, 0.0), o);
    EXPECT_LE(level.median_px, 0.5);
    EXPECT_LE(level.p95_px, 2.0);
    const DriftReport raised = measure_drift(orbit(sphere, "surface", 36, 4.0), o);
    std::cout << "sphere orbit drift (median / p95 px): plain " << plain.median_px << " / " << plain.p95_px
              << ", coherent by image " << coherent.median_px << " / " << coherent.p95_px
              << ", by surface at elevation 0 " << level.median_px << " / " << level.p95_px << ", at 20 "
              << raised.median_px << " / " << raised.p95_px << "\n";
}

TEST(StrokeCoherenceSequence, TorusTurntableDriftsFarLess) {
    // A torus standing on its side (axis along z) turned about the vertical: its outline
    // changes shape every frame. A mark should follow its surface point (projected in the next
    // frame, then onto the new strokes); coherent marks drift a fraction of what arc length
    // from each chain's start gives. What is left is the outline's change of length, which a
    // rigid u = offset + s does not follow (Kalnins et al. also fit a stretch).
    const Mesh torus = builtin::torus();
    DriftOptions o;
    o.expect = DriftExpectation::Surface;
    const DriftReport plain = measure_drift(orbit(torus, "", 36, 5.0), o);
    const DriftReport coherent = measure_drift(orbit(torus, "surface", 36, 5.0), o);
    ASSERT_GT(plain.drifts.size(), 500u);
    ASSERT_GT(coherent.drifts.size(), 500u);
    EXPECT_LE(coherent.median_px, 0.6 * plain.median_px);
    EXPECT_LE(coherent.p95_px, 0.2 * plain.p95_px);
    std::cout << "torus turntable drift (median / p95 px): plain " << plain.median_px << " / " << plain.p95_px << " ("
              << plain.lost << " lost of " << plain.marks << "), coherent " << coherent.median_px << " / "
              << coherent.p95_px << " (" << coherent.lost << " lost of " << coherent.marks << ")\n";
}

TEST(StrokeCoherenceSequence, SingleDrawIsUnchanged) {
    // A coherent layer drawn on its own, or as the first frame of a sequence, draws exactly what
    // it draws without coherence: u is the arc length from each chain's start.
    const Mesh torus = builtin::torus();
    LineExtractor extractor(torus);
    const Camera camera = orbit_camera(30.0, 20.0, 5.0);
    const LineSettings on{"contour", {{"coherence", {1.0f}}, {"dash", {12.0f, 8.0f}}}};
    const LineSettings off{"contour", {{"dash", {12.0f, 8.0f}}}};
    const LineDrawing a = extractor.draw(camera, kWidth, kHeight, {off});
    const LineDrawing b = extractor.draw(camera, kWidth, kHeight, {on});
    StrokeSequence sequence;
    const LineDrawing c = extractor.draw(camera, kWidth, kHeight, {on}, nullptr, &sequence);
    ASSERT_EQ(a.layers[0].visible.size(), b.layers[0].visible.size());
    ASSERT_EQ(a.layers[0].visible.size(), c.layers[0].visible.size());
    for (size_t k = 0; k < a.layers[0].visible.size(); ++k) {
        EXPECT_EQ(a.layers[0].visible[k].points, b.layers[0].visible[k].points);
        EXPECT_TRUE(b.layers[0].visible[k].u.empty());
        ASSERT_EQ(a.layers[0].visible[k].points.size(), c.layers[0].visible[k].points.size());
        for (size_t i = 0; i < a.layers[0].visible[k].points.size(); ++i)
            EXPECT_NEAR(glm::length(a.layers[0].visible[k].points[i] - c.layers[0].visible[k].points[i]), 0.0, 1e-4);
    }
    ASSERT_EQ(sequence.layers.size(), 1u);
    EXPECT_EQ(sequence.layers[0].type, "contour");
    EXPECT_FALSE(sequence.layers[0].paths.empty());
}

}  // namespace
}  // namespace inkshade::geometry
