#include "geometry/dash_pattern.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/path_arc_length.hpp"

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
        const std::vector<double> s = arc_lengths(open);
        const double total = s.back();
        double at = 0.0;
        for (size_t k = 0; at < total; k = (k + 1) % cycle.size()) {
            const double end = std::min(at + cycle[k], total);
            if (k % 2 == 0 && end > at) out.push_back(sub_path(open, s, at, end));
            at = end;
        }
    }
    return out;
}

}  // namespace inkshade::geometry
