// fit_beziers (Schneider 1990): the fitted curve, sampled densely, stays within 0.25 px of the
// polyline and of the analytic curve it samples (circles of known radius, a sine wave), keeps
// a square's corners, uses far fewer pieces than points, and copes with long and degenerate
// input.
#include "io/bezier_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace inkshade::io {
namespace {

constexpr double kPi = 3.14159265358979323846;

double segment_distance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double l2 = glm::dot(ab, ab);
    const double t = l2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

double polyline_distance(glm::dvec2 p, const std::vector<glm::vec2>& line) {
    double best = 1e300;
    for (size_t i = 0; i + 1 < line.size(); ++i)
        best = std::min(best, segment_distance(p, glm::dvec2(line[i]), glm::dvec2(line[i + 1])));
    return best;
}

std::vector<glm::dvec2> samples(const std::vector<CubicBezier>& pieces, int per_piece = 64) {
    std::vector<glm::dvec2> out;
    for (const CubicBezier& b : pieces)
        for (int k = 0; k <= per_piece; ++k) out.push_back(b.at(double(k) / per_piece));
    return out;
}

void expect_continuous(const std::vector<CubicBezier>& pieces, glm::vec2 first, glm::vec2 last) {
    ASSERT_FALSE(pieces.empty());
    EXPECT_EQ(pieces.front().p0, glm::dvec2(first));
    EXPECT_EQ(pieces.back().p3, glm::dvec2(last));
    for (size_t k = 1; k < pieces.size(); ++k) EXPECT_EQ(pieces[k].p0, pieces[k - 1].p3);
}

TEST(BezierFit, CircleStaysWithinAQuarterPixelOfTheCircleAndThePolyline) {
    for (double radius : {3.0, 12.0, 100.0, 400.0}) {
        // A closed circle sampled about every pixel (at least 16 points), passed with its first
        // point again at the end as the SVG writer passes loops.
        const int n = std::max(16, int(2.0 * kPi * radius));
        std::vector<glm::vec2> pts;
        for (int i = 0; i <= n; ++i) {
            const double a = 2.0 * kPi * (i % n) / n;
            pts.emplace_back(float(500.0 + radius * std::cos(a)), float(500.0 + radius * std::sin(a)));
        }
        const std::vector<CubicBezier> fit = fit_beziers(pts, 0.2);
        expect_continuous(fit, pts.front(), pts.back());
        double to_circle = 0.0, to_polyline = 0.0;
        for (glm::dvec2 q : samples(fit)) {
            to_circle = std::max(to_circle, std::abs(glm::length(q - glm::dvec2(500.0)) - radius));
            to_polyline = std::max(to_polyline, polyline_distance(q, pts));
        }
        EXPECT_LE(to_polyline, 0.25) << "radius " << radius;
        // The polyline's own chords sag by r (1 - cos(π / n)) from the circle.
        EXPECT_LE(to_circle, 0.25 + radius * (1.0 - std::cos(kPi / n))) << "radius " << radius;
        EXPECT_LT(fit.size() * 4, pts.size() / 2 + 16) << "radius " << radius << ": far fewer numbers";
    }
}

TEST(BezierFit, NoisySineWaveStaysWithinTheTolerance) {
    // A sine wave with sub-pixel zigzag, as a coarse mesh's interpolated contour has.
    std::vector<glm::vec2> pts;
    for (int i = 0; i <= 2000; ++i) {
        const double x = 0.5 * i;
        pts.emplace_back(float(x), float(200.0 + 60.0 * std::sin(x / 40.0) + ((i % 2) ? 0.08 : -0.08)));
    }
    const std::vector<CubicBezier> fit = fit_beziers(pts, 0.2);
    expect_continuous(fit, pts.front(), pts.back());
    double worst = 0.0;
    for (glm::dvec2 q : samples(fit)) worst = std::max(worst, polyline_distance(q, pts));
    EXPECT_LE(worst, 0.25);
    EXPECT_LT(fit.size(), 60u);
}

TEST(BezierFit, CornersStayCornersAndLinesStayStraight) {
    // A square, a point every pixel: four straight pieces meeting exactly at the corners.
    std::vector<glm::vec2> pts;
    const glm::vec2 c[5] = {{10, 10}, {110, 10}, {110, 110}, {10, 110}, {10, 10}};
    for (int k = 0; k < 4; ++k)
        for (int i = 0; i < 100; ++i) pts.push_back(c[k] + (c[k + 1] - c[k]) * (i / 100.0f));
    pts.push_back(c[4]);
    const std::vector<CubicBezier> fit = fit_beziers(pts, 0.2);
    ASSERT_EQ(fit.size(), 4u);
    for (int k = 0; k < 4; ++k) {
        EXPECT_EQ(fit[k].p0, glm::dvec2(c[k]));
        EXPECT_EQ(fit[k].p3, glm::dvec2(c[k + 1]));
        for (glm::dvec2 q : samples({fit[k]}))
            EXPECT_LT(segment_distance(q, glm::dvec2(c[k]), glm::dvec2(c[k + 1])), 1e-9);
    }
}

TEST(BezierFit, DegenerateAndLongInput) {
    EXPECT_TRUE(fit_beziers({}, 0.2).empty());
    EXPECT_TRUE(fit_beziers({{1, 1}}, 0.2).empty());
    EXPECT_TRUE(fit_beziers({{1, 1}, {1, 1}, {1, 1}}, 0.2).empty()) << "one distinct point";
    EXPECT_TRUE(fit_beziers({{NAN, 1}, {2, 2}}, 0.2).empty());
    // A 200 000-point random walk (a corner at most points): no recursion to exhaust, one
    // continuous curve.
    std::vector<glm::vec2> walk;
    uint32_t state = 12345;
    glm::vec2 p(0.0f);
    for (int i = 0; i < 200000; ++i) {
        state = state * 1664525u + 1013904223u;
        const float a = float(state >> 8) / float(1u << 24) * 6.2831853f;
        p += glm::vec2(std::cos(a), std::sin(a));
        walk.push_back(p);
    }
    const std::vector<CubicBezier> fit = fit_beziers(walk, 0.2);
    expect_continuous(fit, walk.front(), walk.back());
}

}  // namespace
}  // namespace inkshade::io
