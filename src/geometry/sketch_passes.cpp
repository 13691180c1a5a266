#include "geometry/sketch_passes.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/path_arc_length.hpp"
#include "geometry/stroke_noise.hpp"

namespace inkshade::geometry {

std::vector<LinePath> sketch_passes(const std::vector<LinePath>& paths, const SketchOptions& o) {
    const int passes = std::max(o.passes, 1);
    if (passes == 1 && o.jitter_px <= 0.0f) return paths;
    std::vector<LinePath> out;
    out.reserve(paths.size() * size_t(passes));
    const double period = std::max(double(o.period_px), 1e-3);
    for (size_t k = 0; k < paths.size(); ++k) {
        const LinePath& path = paths[k];
        // A coherent stroke's jitter follows its parameter u and not its index in this frame,
        // so it stays on the surface from frame to frame.
        const bool coherent = path.u.size() == path.points.size();
        std::vector<double> s = arc_lengths(path);
        if (coherent) s.assign(path.u.begin(), path.u.end());
        const auto stroke = uint32_t(coherent ? 0 : k);
        for (int pass = 0; pass < passes; ++pass) {
            LinePath copy = path;
            // A different phase per pass, so copies of one stroke do not wobble in step.
            const uint32_t sx = noise_stream(stroke, uint32_t(pass), 1);
            const uint32_t sy = noise_stream(stroke, uint32_t(pass), 2);
            for (size_t i = 0; i < copy.points.size(); ++i) {
                glm::dvec2 d(value_noise(o.seed, sx, s[i] / period), value_noise(o.seed, sy, s[i] / period));
                // Each component is in [-1, 1]; the disc keeps the displacement within jitter.
                const double len = glm::length(d);
                if (len > 1.0) d /= len;
                copy.points[i] += glm::vec2(d * double(o.jitter_px));
            }
            out.push_back(std::move(copy));
        }
    }
    return out;
}

}  // namespace inkshade::geometry
