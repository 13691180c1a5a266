#include "io/stroke_outline.hpp"

#include <algorithm>
#include <cmath>

namespace inkshade::io {

namespace {

constexpr double kPi = 3.14159265358979323846;

glm::dvec2 unit(glm::dvec2 v) {
    const double l = glm::length(v);
    return l > 0.0 ? v / l : glm::dvec2(0.0);
}

glm::dvec2 normal_of(glm::dvec2 t) { return {-t.y, t.x}; }

}  // namespace

StrokeOutline stroke_outline(const std::vector<glm::vec2>& points_in, const std::vector<float>& widths_in, bool closed,
                             geometry::StrokeJoin join) {
    // Drop repeated points (no direction there), keeping each kept point's width.
    std::vector<glm::dvec2> p;
    std::vector<double> r;
    for (size_t i = 0; i < points_in.size(); ++i) {
        const glm::dvec2 q(points_in[i]);
        const double w =
            i < widths_in.size() && std::isfinite(widths_in[i]) ? std::max(double(widths_in[i]), 0.0) : 0.0;
        if (!p.empty() && glm::length(q - p.back()) <= 1e-9) {
            r.back() = std::max(r.back(), 0.5 * w);
            continue;
        }
        p.push_back(q);
        r.push_back(0.5 * w);
    }
    if (closed && p.size() > 1 && glm::length(p.front() - p.back()) <= 1e-9) {
        p.pop_back();
        r.pop_back();
    }
    StrokeOutline out;
    out.closed = closed && p.size() > 2;
    const size_t n = p.size();
    if (n < 2) return out;
    const double join_cos = std::cos(kOutlineJoinDegrees * kPi / 180.0);
    auto emit = [&](std::vector<glm::vec2>& side, glm::dvec2 q) { side.emplace_back(glm::vec2(q)); };
    for (size_t i = 0; i < n; ++i) {
        const bool has_in = out.closed || i > 0, has_out = out.closed || i + 1 < n;
        const glm::dvec2 t_in = has_in ? unit(p[i] - p[(i + n - 1) % n]) : glm::dvec2(0.0);
        const glm::dvec2 t_out = has_out ? unit(p[(i + 1) % n] - p[i]) : glm::dvec2(0.0);
        if (!has_in || !has_out) {  // an open end: the end segment's normal
            const glm::dvec2 nrm = normal_of(has_in ? t_in : t_out);
            emit(out.left, p[i] + nrm * r[i]);
            emit(out.right, p[i] - nrm * r[i]);
            continue;
        }
        const glm::dvec2 n_in = normal_of(t_in), n_out = normal_of(t_out);
        glm::dvec2 bis = unit(n_in + n_out);
        if (bis == glm::dvec2(0.0)) bis = n_in;  // the stroke turns right back
        const double c = glm::dot(bis, n_in);    // cos of half the turn
        const double miter = c > 1.0 / kMiterLimit ? 1.0 / c : kMiterLimit;
        if (glm::dot(t_in, t_out) >= join_cos) {
            emit(out.left, p[i] + bis * (r[i] * miter));
            emit(out.right, p[i] - bis * (r[i] * miter));
            continue;
        }
        // A corner: the side it turns away from is the outer one.
        const bool left_outer = t_in.x * t_out.y - t_in.y * t_out.x < 0.0;
        const double s = left_outer ? 1.0 : -1.0;
        std::vector<glm::vec2>& outer = left_outer ? out.left : out.right;
        std::vector<glm::vec2>& inner = left_outer ? out.right : out.left;
        emit(inner, p[i] - s * bis * (r[i] * miter));
        const glm::dvec2 a = s * n_in, b = s * n_out;
        if (join == geometry::StrokeJoin::Miter && c > 1.0 / kMiterLimit) {
            emit(outer, p[i] + s * bis * (r[i] / c));
        } else if (join == geometry::StrokeJoin::Round) {
            // The arc from a to b about p[i], a point every 10° at most.
            const double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
            const int steps = std::max(1, int(std::ceil(angle / (10.0 * kPi / 180.0))));
            const double turn = a.x * b.y - a.y * b.x >= 0.0 ? 1.0 : -1.0;
            for (int k = 0; k <= steps; ++k) {
                const double phi = turn * angle * k / steps;
                const glm::dvec2 d(a.x * std::cos(phi) - a.y * std::sin(phi),
                                   a.x * std::sin(phi) + a.y * std::cos(phi));
                emit(outer, p[i] + d * r[i]);
            }
        } else {  // bevel, or a miter past the limit
            emit(outer, p[i] + a * r[i]);
            emit(outer, p[i] + b * r[i]);
        }
    }
    return out;
}

}  // namespace inkshade::io
