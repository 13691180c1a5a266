#include "geometry/path_arc_length.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/path_attributes.hpp"

namespace inkshade::geometry {

namespace {

// Appends to `out` the attributes of `p` at point i, or between i and i + 1 at fraction f.
void append_point(LinePath& out, const LinePath& p, size_t i, float f) {
    const size_t j = std::min(i + 1, p.points.size() - 1);
    auto mix = [&](auto& to, const auto& v) {
        if (!v.empty()) to.push_back(interpolated(v[i], v[j], f));
    };
    for_each_point_attribute(mix, out, p);
}

// The stroke parameter past a closed path's last point, at its first point again: u runs on
// over the closing segment (u = offset + arc length).
float u_after_loop(const LinePath& p) { return p.u.back() + glm::length(p.points.front() - p.points.back()); }

// The segment index i and fraction f where arc length t falls (s ascending, t clamped).
std::pair<size_t, float> locate(const std::vector<double>& s, double t) {
    const size_t n = s.size();
    if (t <= s.front()) return {0, 0.0f};
    if (t >= s.back()) return {n - 1, 0.0f};
    const size_t i = size_t(std::upper_bound(s.begin(), s.end(), t) - s.begin()) - 1;
    const double len = s[i + 1] - s[i];
    return {i, len > 0.0 ? float((t - s[i]) / len) : 0.0f};
}

}  // namespace

std::vector<double> arc_lengths(const LinePath& path) {
    const size_t n = path.points.size();
    std::vector<double> s(n + (path.closed && n > 1 ? 1 : 0), 0.0);
    for (size_t i = 1; i < s.size(); ++i)
        s[i] = s[i - 1] + double(glm::length(path.points[i % n] - path.points[i - 1]));
    return s;
}

LinePath opened(const LinePath& path) {
    if (!path.closed || path.points.size() < 2) return path;
    LinePath out = path;
    out.closed = false;
    append_point(out, path, 0, 0.0f);
    if (!path.u.empty()) out.u.back() = u_after_loop(path);
    return out;
}

LinePath rotated(const LinePath& path, size_t k) {
    LinePath out = path;
    auto turn = [&](auto& v) {
        if (!v.empty()) std::rotate(v.begin(), v.begin() + long(k % v.size()), v.end());
    };
    for_each_point_attribute(turn, out);
    if (!path.u.empty() && !path.points.empty()) {
        // u stays increasing: the points that wrapped around come after the loop's last one.
        const size_t n = path.u.size(), first = k % n;
        const float lap = u_after_loop(path) - path.u.front();
        for (size_t i = 0; i < n; ++i) out.u[i] = path.u[(first + i) % n] + (first + i >= n ? lap : 0.0f);
    }
    return out;
}

LinePath sub_path(const LinePath& open, const std::vector<double>& s, double s0, double s1) {
    LinePath out;
    out.level = open.level;
    if (open.points.empty()) return out;
    const auto [i0, f0] = locate(s, s0);
    const auto [i1, f1] = locate(s, s1);
    append_point(out, open, i0, f0);
    for (size_t i = i0 + 1; i <= i1; ++i)
        if (!(i == i1 && f1 == 0.0f)) append_point(out, open, i, 0.0f);
    append_point(out, open, i1, f1);
    return out;
}

}  // namespace inkshade::geometry
