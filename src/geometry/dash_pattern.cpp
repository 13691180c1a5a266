#include "geometry/dash_pattern.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/path_arc_length.hpp"
#include "geometry/path_attributes.hpp"

namespace inkshade::geometry {

std::vector<LinePath> dash_paths(const std::vector<LinePath>& paths, const std::vector<float>& pattern) {
    std::vector<double> cycle;
    for (float v : pattern) cycle.push_back(std::isfinite(v) ? std::max(double(v), 0.0) : 0.0);
    if (cycle.size() % 2 == 1) cycle.insert(cycle.end(), cycle.begin(), cycle.end());
    double period = 0.0;
    for (double v : cycle) period += v;
    if (cycle.empty() || !(period > 0.0)) return paths;
    double on_total = 0.0;
    for (size_t k = 0; k < cycle.size(); k += 2) on_total += cycle[k];
    if (on_total <= 0.0) return {};  // all gaps: nothing drawn

    std::vector<LinePath> out;
    for (const LinePath& path : paths) {
        if (path.points.size() < 2 || !attributes_consistent(path)) continue;
        const LinePath open = opened(path);
        // A coherent stroke's pattern is anchored to its parameter u (offset + arc length), so
        // the dashes stay where the previous frame had them; else it starts at the path's start.
        std::vector<double> s;
        if (open.u.size() == open.points.size()) s.assign(open.u.begin(), open.u.end());
        if (s.empty() || !std::is_sorted(s.begin(), s.end())) s = arc_lengths(open);
        double at = s.front();
        const double total = s.back();
        // Where `at` falls in the pattern: entry k with `left` pixels of it still to go.
        double phase = at - period * std::floor(at / period);
        size_t k = 0;
        while (k + 1 < cycle.size() && phase >= cycle[k]) phase -= cycle[k++];
        double left = std::max(cycle[k] - phase, 0.0);
        while (at < total) {
            const double end = std::min(at + left, total);
            if (k % 2 == 0 && end > at) out.push_back(sub_path(open, s, at, end));
            at = end;
            k = (k + 1) % cycle.size();
            left = cycle[k];
        }
    }
    return out;
}

}  // namespace inkshade::geometry
