#include "geometry/stroke_thickness.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/path_arc_length.hpp"
#include "geometry/stroke_noise.hpp"

namespace inkshade::geometry {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Curvature of the circle through a, b, c (0 when they are collinear or coincide).
double circumcircle_curvature(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    const glm::dvec2 ab = b - a, bc = c - b, ac = c - a;
    const double denom = glm::length(ab) * glm::length(bc) * glm::length(ac);
    if (!(denom > 0.0)) return 0.0;
    return 2.0 * std::abs(ab.x * ac.y - ab.y * ac.x) / denom;
}

}  // namespace

bool StrokeThickness::varies() const {
    return strength_scales || taper_in_px > 0.0f || taper_out_px > 0.0f || depth_factors.x != depth_factors.y ||
           curvature_factors.x != curvature_factors.y || level_factor != 1.0f || calligraphy > 0.0f || noise > 0.0f;
}

std::vector<float> image_curvature(const LinePath& path) {
    const size_t n = path.points.size();
    std::vector<float> k(n, 0.0f);
    if (n < 3) return k;
    const std::vector<double> s = arc_lengths(path);
    const double total = s.back();
    const bool loop = path.closed;
    for (size_t i = 0; i < n; ++i) {
        // The nearest vertices at least kCurvatureSpanPx away along the path on each side.
        size_t before = i, after = i;
        bool found_before = false, found_after = false;
        for (size_t step = 1; step < n; ++step) {
            if (!loop && step > i) break;
            const size_t j = (i + n - step) % n;
            const double d = loop ? std::fmod(s[i] - s[j] + total, total) : s[i] - s[j];
            before = j;
            found_before = true;
            if (d >= kCurvatureSpanPx) break;
        }
        for (size_t step = 1; step < n; ++step) {
            if (!loop && i + step >= n) break;
            const size_t j = (i + step) % n;
            const double d = loop ? std::fmod(s[j] - s[i] + total, total) : s[j] - s[i];
            after = j;
            found_after = true;
            if (d >= kCurvatureSpanPx) break;
        }
        if (found_before && found_after && before != after)
            k[i] = float(circumcircle_curvature(path.points[before], path.points[i], path.points[after]));
    }
    // An open path's ends take their neighbour's value (no circle through an end).
    if (!loop) {
        k[0] = k[1];
        k[n - 1] = k[n - 2];
    }
    return k;
}

std::vector<float> stroke_widths(const LinePath& path, const StrokeThickness& t, const ViewDepthRange& depth,
                                 uint32_t stream) {
    const size_t n = path.points.size();
    std::vector<float> w(n, std::max(t.width, 0.0f));
    if (n == 0) return w;
    const std::vector<double> s = arc_lengths(path);
    const double total = path.closed ? s[n - 1] : s.back();
    const float level = std::pow(t.level_factor, float(path.level));
    std::vector<float> curvature;
    if (t.curvature_factors.x != t.curvature_factors.y) curvature = image_curvature(path);
    const double nib = double(t.nib_angle_degrees) * kPi / 180.0;
    const glm::dvec2 nib_dir(std::cos(nib), -std::sin(nib));  // image y points down
    for (size_t i = 0; i < n; ++i) {
        double f = level;
        if (t.strength_scales && path.strength.size() == n) f *= std::clamp(double(path.strength[i]), 0.0, 1.0);
        if (!path.closed) {
            if (t.taper_in_px > 0.0f) f *= std::min(1.0, s[i] / double(t.taper_in_px));
            if (t.taper_out_px > 0.0f) f *= std::min(1.0, (total - s[i]) / double(t.taper_out_px));
        }
        if (t.depth_factors.x != t.depth_factors.y && path.depth.size() == n)
            f *= glm::mix(double(t.depth_factors.x), double(t.depth_factors.y), double(depth.fraction(path.depth[i])));
        if (!curvature.empty()) {
            const double a = std::clamp(double(curvature[i]) * double(t.curvature_radius_px), 0.0, 1.0);
            f *= glm::mix(double(t.curvature_factors.x), double(t.curvature_factors.y), a);
        }
        if (t.calligraphy > 0.0f && n > 1) {
            // Central difference; one-sided at an open path's ends.
            const size_t a = path.closed ? (i + n - 1) % n : (i == 0 ? 0 : i - 1);
            const size_t b = path.closed ? (i + 1) % n : std::min(i + 1, n - 1);
            const glm::dvec2 d = glm::dvec2(path.points[b]) - glm::dvec2(path.points[a]);
            const double len = glm::length(d);
            const double along = len > 0.0 ? std::abs(glm::dot(d / len, nib_dir)) : 1.0;
            f *= 1.0 - double(t.calligraphy) * (1.0 - along);
        }
        if (t.noise > 0.0f) {
            const double period = std::max(double(t.noise_period_px), 1e-3);
            // A coherent stroke's noise follows its parameter u, so it stays on the surface.
            const double at = path.u.size() == n ? double(path.u[i]) : s[i];
            f *= 1.0 + double(t.noise) * double(value_noise(t.seed, stream, at / period));
        }
        w[i] = float(std::max(0.0, double(t.width) * f));
    }
    return w;
}

}  // namespace inkshade::geometry
