#include "io/bezier_fit.hpp"

#include <algorithm>
#include <cmath>

namespace inkshade::io {

glm::dvec2 CubicBezier::at(double t) const {
    const double s = 1.0 - t;
    return s * s * s * p0 + 3.0 * s * s * t * p1 + 3.0 * s * t * t * p2 + t * t * t * p3;
}

namespace {

using Points = std::vector<glm::dvec2>;

glm::dvec2 derivative(const CubicBezier& b, double t) {
    const double s = 1.0 - t;
    return 3.0 * (s * s * (b.p1 - b.p0) + 2.0 * s * t * (b.p2 - b.p1) + t * t * (b.p3 - b.p2));
}

glm::dvec2 second_derivative(const CubicBezier& b, double t) {
    return 6.0 * ((1.0 - t) * (b.p2 - 2.0 * b.p1 + b.p0) + t * (b.p3 - 2.0 * b.p2 + b.p1));
}

glm::dvec2 unit(glm::dvec2 v) {
    const double l = glm::length(v);
    return l > 0.0 ? v / l : glm::dvec2(0.0);
}

double segment_distance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 ab = b - a;
    const double l2 = glm::dot(ab, ab);
    const double t = l2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

// The direction leaving d[i] towards d[i + step] (step = ±1), from the first point at least
// kTangentSpan away within [first, last], so sub-pixel noise does not set the tangent.
constexpr double kTangentSpan = 1.5;
glm::dvec2 tangent_from(const Points& d, size_t i, int step, size_t first, size_t last) {
    glm::dvec2 v(0.0);
    for (long j = long(i) + step; j >= long(first) && j <= long(last); j += step) {
        v = d[size_t(j)] - d[i];
        if (glm::length(v) >= kTangentSpan) break;
    }
    return unit(v);
}

std::vector<double> chord_parameters(const Points& d, size_t first, size_t last) {
    std::vector<double> u(last - first + 1, 0.0);
    for (size_t i = first + 1; i <= last; ++i) u[i - first] = u[i - first - 1] + glm::length(d[i] - d[i - 1]);
    const double total = u.back();
    for (double& v : u) v = total > 0.0 ? v / total : 0.0;
    return u;
}

// Least-squares lengths of the end tangents (Schneider's GenerateBezier), with the
// Wu–Barsky heuristic (a third of the chord) when the system is degenerate.
CubicBezier generate(const Points& d, size_t first, size_t last, const std::vector<double>& u, glm::dvec2 t1,
                     glm::dvec2 t2) {
    const glm::dvec2 p0 = d[first], p3 = d[last];
    double c00 = 0, c01 = 0, c11 = 0, x0 = 0, x1 = 0;
    for (size_t i = first; i <= last; ++i) {
        const double t = u[i - first], s = 1.0 - t;
        const double b0 = s * s * s, b1 = 3 * s * s * t, b2 = 3 * s * t * t, b3 = t * t * t;
        const glm::dvec2 a1 = t1 * b1, a2 = t2 * b2;
        c00 += glm::dot(a1, a1);
        c01 += glm::dot(a1, a2);
        c11 += glm::dot(a2, a2);
        const glm::dvec2 tmp = d[i] - (p0 * (b0 + b1) + p3 * (b2 + b3));
        x0 += glm::dot(a1, tmp);
        x1 += glm::dot(a2, tmp);
    }
    const double det = c00 * c11 - c01 * c01;
    double al = 0.0, ar = 0.0;
    if (std::abs(det) > 1e-12 * std::max(1.0, c00 * c11)) {
        al = (x0 * c11 - x1 * c01) / det;
        ar = (c00 * x1 - c01 * x0) / det;
    }
    const double chord = glm::length(p3 - p0);
    const double eps = 1e-6 * chord;
    if (!(al >= eps) || !(ar >= eps) || !std::isfinite(al) || !std::isfinite(ar)) al = ar = chord / 3.0;
    return {p0, p0 + t1 * al, p3 + t2 * ar, p3};
}

// The largest distance of the points from the curve at their parameters and of the curve
// halfway between parameters from the segment there; `split` = the worst interior point.
double max_error(const Points& d, size_t first, size_t last, const CubicBezier& b, const std::vector<double>& u,
                 size_t& split) {
    double worst = 0.0;
    split = (first + last) / 2;
    for (size_t i = first; i <= last; ++i) {
        const double e = glm::length(b.at(u[i - first]) - d[i]);
        if (e > worst) {
            worst = e;
            split = i;
        }
        if (i < last) {
            const double m = segment_distance(b.at(0.5 * (u[i - first] + u[i + 1 - first])), d[i], d[i + 1]);
            if (m > worst) {
                worst = m;
                split = i + 1 < last ? i + 1 : i;
            }
        }
    }
    split = std::clamp(split, first + 1, last - 1);
    return worst;
}

// One Newton–Raphson step per point towards the curve's closest parameter.
void reparameterise(const Points& d, size_t first, const CubicBezier& b, std::vector<double>& u) {
    for (size_t k = 0; k < u.size(); ++k) {
        const glm::dvec2 q = b.at(u[k]) - d[first + k], q1 = derivative(b, u[k]), q2 = second_derivative(b, u[k]);
        const double den = glm::dot(q1, q1) + glm::dot(q, q2);
        if (std::abs(den) > 1e-12) u[k] = std::clamp(u[k] - glm::dot(q, q1) / den, 0.0, 1.0);
    }
}

struct Range {
    size_t first, last;
    glm::dvec2 t1, t2;
};

// Fits d[first..last] (no corner inside) into `out`, splitting iteratively (no recursion, so
// a long polyline cannot exhaust the stack).
void fit_range(const Points& d, size_t first, size_t last, double error, std::vector<CubicBezier>& out) {
    std::vector<Range> stack{
        {first, last, tangent_from(d, first, 1, first, last), tangent_from(d, last, -1, first, last)}};
    while (!stack.empty()) {
        const Range r = stack.back();
        stack.pop_back();
        if (r.last - r.first == 1) {
            const glm::dvec2 a = d[r.first], b = d[r.last];
            out.push_back({a, a + (b - a) / 3.0, b - (b - a) / 3.0, b});
            continue;
        }
        std::vector<double> u = chord_parameters(d, r.first, r.last);
        CubicBezier bez = generate(d, r.first, r.last, u, r.t1, r.t2);
        size_t split = 0;
        double e = max_error(d, r.first, r.last, bez, u, split);
        for (int iteration = 0; e > error && e < 4.0 * error && iteration < 4; ++iteration) {
            reparameterise(d, r.first, bez, u);
            bez = generate(d, r.first, r.last, u, r.t1, r.t2);
            e = max_error(d, r.first, r.last, bez, u, split);
        }
        if (e <= error) {
            out.push_back(bez);
            continue;
        }
        // Split at the worst point with a common tangent; the later half is pushed first so the
        // pieces come out in order.
        glm::dvec2 centre =
            unit(tangent_from(d, split, -1, r.first, r.last) - tangent_from(d, split, 1, r.first, r.last));
        if (centre == glm::dvec2(0.0)) centre = unit(d[split - 1] - d[split + 1]);
        stack.push_back({split, r.last, -centre, r.t2});
        stack.push_back({r.first, split, r.t1, centre});
    }
}

}  // namespace

std::vector<CubicBezier> fit_beziers(const std::vector<glm::vec2>& points, double max_error_px) {
    Points d;
    d.reserve(points.size());
    for (const glm::vec2& p : points) {
        const glm::dvec2 q(p);
        if (!std::isfinite(q.x) || !std::isfinite(q.y)) continue;
        if (d.empty() || glm::length(q - d.back()) > 1e-9) d.push_back(q);
    }
    std::vector<CubicBezier> out;
    if (d.size() < 2) return out;
    // Corners: the direction over kTangentSpan before and after a vertex turns more than the limit.
    const double corner_cos = std::cos(kBezierCornerDegrees * 3.14159265358979323846 / 180.0);
    size_t start = 0;
    for (size_t i = 1; i + 1 < d.size(); ++i) {
        const glm::dvec2 in = -tangent_from(d, i, -1, 0, d.size() - 1),
                         out_dir = tangent_from(d, i, 1, 0, d.size() - 1);
        const glm::dvec2 a = unit(d[i] - d[i - 1]), b = unit(d[i + 1] - d[i]);
        if (glm::dot(in, out_dir) < corner_cos && glm::dot(a, b) < corner_cos) {
            fit_range(d, start, i, max_error_px, out);
            start = i;
        }
    }
    fit_range(d, start, d.size() - 1, max_error_px, out);
    return out;
}

}  // namespace inkshade::io
