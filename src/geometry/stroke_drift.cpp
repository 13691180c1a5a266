#include "geometry/stroke_drift.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/path_arc_length.hpp"
#include "geometry/visibility.hpp"

namespace inkshade::geometry {

namespace {

// A frame's strokes of one layer, visible level, opened (a loop's first point repeated, its u
// run on), with arc lengths.
struct Stroke {
    LinePath open;
    std::vector<double> s;
    double length = 0.0;
    bool closed = false;
};

std::vector<Stroke> strokes_of(const StrokeSequence& frame, const std::string& type) {
    std::vector<Stroke> out;
    for (const ParameterisedLayer& layer : frame.layers) {
        if (layer.type != type) continue;
        for (const LinePath& p : layer.paths) {
            if (p.level != 0 || p.points.size() < 2 || p.u.size() != p.points.size()) continue;
            Stroke st;
            st.open = opened(p);
            st.s = arc_lengths(st.open);
            st.length = st.s.back();
            st.closed = p.closed;
            if (std::is_sorted(st.open.u.begin(), st.open.u.end())) out.push_back(std::move(st));
        }
        break;
    }
    return out;
}

// Segment i and fraction t where u = value on the stroke (u ascending), or i = -1 outside it.
std::pair<long, double> at_u(const Stroke& st, double value) {
    const std::vector<float>& u = st.open.u;
    if (value < double(u.front()) || value > double(u.back())) return {-1, 0.0};
    const auto it = std::upper_bound(u.begin(), u.end(), float(value));
    const size_t i = std::min(size_t(std::max<long>(long(it - u.begin()) - 1, 0)), u.size() - 2);
    const double du = double(u[i + 1]) - double(u[i]);
    return {long(i), du > 0.0 ? std::clamp((value - double(u[i])) / du, 0.0, 1.0) : 0.0};
}

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const double at = q * double(v.size() - 1);
    const auto i = size_t(at);
    const double f = at - double(i);
    return i + 1 < v.size() ? v[i] + (v[i + 1] - v[i]) * f : v[i];
}

}  // namespace

DriftReport measure_drift(const std::vector<StrokeSequence>& frames, const DriftOptions& o) {
    DriftReport report;
    const double period = std::max(double(o.period_px), 1e-3);
    for (size_t t = 0; t + 1 < frames.size(); ++t) {
        const std::vector<Stroke> a = strokes_of(frames[t], o.type), b = strokes_of(frames[t + 1], o.type);
        const StrokeSequence& next = frames[t + 1];
        const ImageProjection view(next.camera, std::max(next.width, 1), std::max(next.height, 1));
        for (const Stroke& st : a) {
            const auto k0 = long(std::ceil(double(st.open.u.front()) / period));
            const auto k1 = long(std::floor(double(st.open.u.back()) / period));
            for (long k = k0; k <= k1; ++k) {
                const auto [i, f] = at_u(st, double(k) * period);
                if (i < 0) continue;
                // A loop's mark at its very end is its mark at the start: counted once.
                if (st.closed && size_t(i) + 2 == st.open.points.size() && f >= 1.0) continue;
                ++report.marks;
                const auto j = size_t(i);
                glm::dvec2 expected = glm::dvec2(st.open.points[j]) +
                                      (glm::dvec2(st.open.points[j + 1]) - glm::dvec2(st.open.points[j])) * f;
                if (o.expect == DriftExpectation::Surface && st.open.world.size() == st.open.points.size()) {
                    const glm::dvec3 w = glm::dvec3(st.open.world[j]) +
                                         (glm::dvec3(st.open.world[j + 1]) - glm::dvec3(st.open.world[j])) * f;
                    const glm::dvec3 q = view.project(glm::vec3(w));
                    expected = {q.x, q.y};
                }
                // The matched stroke: the next frame's stroke nearest the expected place.
                double best = double(o.radius_px) * double(o.radius_px);
                const Stroke* match = nullptr;
                double s_expected = 0.0;
                for (const Stroke& nb : b)
                    for (size_t m = 0; m + 1 < nb.open.points.size(); ++m) {
                        const glm::dvec2 p(nb.open.points[m]), q(nb.open.points[m + 1]);
                        const glm::dvec2 d = q - p;
                        const double l2 = glm::dot(d, d);
                        const double tt = l2 > 0.0 ? std::clamp(glm::dot(expected - p, d) / l2, 0.0, 1.0) : 0.0;
                        const glm::dvec2 e = p + d * tt - expected;
                        if (glm::dot(e, e) < best) {
                            best = glm::dot(e, e);
                            match = &nb;
                            s_expected = nb.s[m] + (nb.s[m + 1] - nb.s[m]) * tt;
                        }
                    }
                if (!match) {
                    ++report.unmatched;
                    continue;
                }
                const auto [mi, mf] = at_u(*match, double(k) * period);
                if (mi < 0) {
                    ++report.lost;
                    continue;
                }
                const double s_mark = match->s[size_t(mi)] + (match->s[size_t(mi) + 1] - match->s[size_t(mi)]) * mf;
                double drift = std::abs(s_mark - s_expected);
                if (match->closed) drift = std::min(drift, match->length - drift);
                report.drifts.push_back(drift);
            }
        }
    }
    report.median_px = percentile(report.drifts, 0.5);
    report.p95_px = percentile(report.drifts, 0.95);
    report.max_px = report.drifts.empty() ? 0.0 : *std::max_element(report.drifts.begin(), report.drifts.end());
    return report;
}

}  // namespace inkshade::geometry
