#include "geometry/chain_split.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/path_arc_length.hpp"
#include "geometry/path_attributes.hpp"

namespace inkshade::geometry {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Angle in degrees between directions a and b (0 when either is zero).
double turn_degrees(glm::dvec2 a, glm::dvec2 b) {
    const double la = glm::length(a), lb = glm::length(b);
    if (la <= 0.0 || lb <= 0.0) return 0.0;
    return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0)) * 180.0 / kPi;
}

// The point at arc length t of a path with arc lengths s (a closed path wraps around).
glm::dvec2 point_at(const LinePath& p, const std::vector<double>& s, double t) {
    const size_t n = p.points.size();
    const double total = s.back();
    if (p.closed && total > 0.0) t = std::fmod(std::fmod(t, total) + total, total);
    t = std::clamp(t, 0.0, total);
    const size_t i = std::min(size_t(std::upper_bound(s.begin(), s.end(), t) - s.begin()), s.size() - 1) - 1;
    const double len = s[i + 1] - s[i];
    const double f = len > 0.0 ? (t - s[i]) / len : 0.0;
    return glm::mix(glm::dvec2(p.points[i]), glm::dvec2(p.points[(i + 1) % n]), f);
}

// Vertices where the stroke ends, ascending.
std::vector<size_t> split_points(const LinePath& p, const ChainSplitOptions& o) {
    const size_t n = p.points.size();
    std::vector<size_t> out;
    if (n < 3) return out;
    const size_t first = p.closed ? 0 : 1, last = p.closed ? n : n - 1;
    // Immediate turns: the nearest distinct neighbour on each side (repeated points skipped).
    std::vector<double> turn(n, 0.0);
    for (size_t i = first; i < last; ++i) {
        const glm::dvec2 q(p.points[i]);
        glm::dvec2 in(0.0), out_dir(0.0);
        for (size_t k = 1; k < n && in == glm::dvec2(0.0); ++k) {
            if (!p.closed && k > i) break;
            in = q - glm::dvec2(p.points[(i + n - k) % n]);
        }
        for (size_t k = 1; k < n && out_dir == glm::dvec2(0.0); ++k) {
            if (!p.closed && i + k >= n) break;
            out_dir = glm::dvec2(p.points[(i + k) % n]) - q;
        }
        turn[i] = turn_degrees(in, out_dir);
    }
    std::vector<bool> split(n, false);
    if (o.split_angle_degrees > 0.0f)
        for (size_t i = first; i < last; ++i) split[i] = turn[i] > double(o.split_angle_degrees);
    if (o.cusps) {
        const std::vector<double> s = arc_lengths(p);
        const double h = kCuspChordPx;
        std::vector<double> chord_turn(n, 0.0);
        for (size_t i = first; i < last; ++i) {
            if (!p.closed && (s[i] < h || s[n - 1] - s[i] < h)) continue;  // no chord before or after
            const glm::dvec2 q(p.points[i]);
            chord_turn[i] = turn_degrees(q - point_at(p, s, s[i] - h), point_at(p, s, s[i] + h) - q);
        }
        // The most turning vertex among those within h of each other that exceed the limit.
        for (size_t i = first; i < last; ++i) {
            if (chord_turn[i] <= kCuspTurnDegrees) continue;
            bool peak = true;
            for (size_t k = 1; k < n && peak; ++k) {
                if (!p.closed && k > i) break;
                const size_t j = (i + n - k) % n;
                const double d = p.closed ? std::fmod(s[i] - s[j] + s.back(), s.back()) : s[i] - s[j];
                if (d > h) break;
                peak = chord_turn[j] < chord_turn[i];  // ties: the first of the run
            }
            for (size_t k = 1; k < n && peak; ++k) {
                if (!p.closed && i + k >= n) break;
                const size_t j = (i + k) % n;
                const double d = p.closed ? std::fmod(s[j] - s[i] + s.back(), s.back()) : s[j] - s[i];
                if (d > h) break;
                peak = chord_turn[j] <= chord_turn[i];
            }
            if (peak) split[i] = true;
        }
    }
    for (size_t i = 0; i < n; ++i)
        if (split[i]) out.push_back(i);
    return out;
}

// The piece of p from vertex a to vertex b (inclusive), attributes kept.
LinePath vertex_range(const LinePath& p, size_t a, size_t b) {
    LinePath out;
    out.level = p.level;
    auto take = [&](auto& to, const auto& from) {
        if (!from.empty()) to.assign(from.begin() + long(a), from.begin() + long(b) + 1);
    };
    for_each_point_attribute(take, out, p);
    return out;
}

void cut_to_length(LinePath piece, double max_length, std::vector<LinePath>& out) {
    if (max_length <= 0.0 || piece.points.size() < 2) {
        out.push_back(std::move(piece));
        return;
    }
    const std::vector<double> s0 = arc_lengths(piece);
    if (s0.back() <= max_length) {
        out.push_back(std::move(piece));
        return;
    }
    const LinePath open = opened(piece);
    const std::vector<double> s = arc_lengths(open);
    const double total = s.back();
    const auto count = size_t(std::ceil(total / max_length - 1e-9));
    for (size_t k = 0; k < count; ++k)
        out.push_back(sub_path(open, s, total * double(k) / double(count), total * double(k + 1) / double(count)));
}

}  // namespace

std::vector<LinePath> split_chains(const std::vector<LinePath>& paths, const ChainSplitOptions& options) {
    std::vector<LinePath> out;
    out.reserve(paths.size());
    const double max_length = options.max_length_px;
    for (const LinePath& path : paths) {
        if (!attributes_consistent(path) || path.points.size() < 2) {
            out.push_back(path);
            continue;
        }
        const std::vector<size_t> cuts = split_points(path, options);
        if (cuts.empty()) {
            cut_to_length(path, max_length, out);
            continue;
        }
        // A loop starts at its first cut and ends there again.
        const LinePath open = path.closed ? opened(rotated(path, cuts.front())) : path;
        std::vector<size_t> at;
        for (size_t c : cuts) at.push_back(path.closed ? c - cuts.front() : c);
        if (at.front() != 0) at.insert(at.begin(), 0);
        if (at.back() != open.points.size() - 1) at.push_back(open.points.size() - 1);
        for (size_t k = 0; k + 1 < at.size(); ++k) cut_to_length(vertex_range(open, at[k], at[k + 1]), max_length, out);
    }
    return out;
}

}  // namespace inkshade::geometry
