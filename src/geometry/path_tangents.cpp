// path_tangents (line_drawing.hpp): the image tangent of each point of a path, from the path's
// own points, as the finite differences a learner reading --lines-json would take.
#include <cmath>

#include "inkshade/line_drawing.hpp"

namespace inkshade {

namespace {

// The first point from i, stepping by `step` (±1), that differs from points[i]; i itself when
// there is none (an open path's end, or a loop of one repeated point).
size_t distinct_neighbour(const LinePath& p, size_t i, int step) {
    const size_t n = p.points.size();
    size_t j = i;
    for (size_t k = 1; k < n; ++k) {
        if (!p.closed && ((step < 0 && j == 0) || (step > 0 && j + 1 == n))) return i;
        j = step > 0 ? (j + 1) % n : (j + n - 1) % n;
        if (p.points[j] != p.points[i]) return j;
    }
    return i;
}

}  // namespace

std::vector<glm::vec2> path_tangents(const LinePath& path) {
    const size_t n = path.points.size();
    std::vector<glm::vec2> out(n, glm::vec2(1.0f, 0.0f));
    const auto at = [&](size_t i) { return glm::dvec2(path.points[i]); };
    for (size_t i = 0; i < n; ++i) {
        const size_t next = distinct_neighbour(path, i, +1), prev = distinct_neighbour(path, i, -1);
        // Central difference of the neighbours (at an open end the one-sided one); where the
        // path turns straight back, the forward one.
        for (const glm::dvec2 d : {at(next) - at(prev), at(next) - at(i), at(i) - at(prev)}) {
            const double len = glm::length(d);
            if (len > 0.0 && std::isfinite(len)) {
                out[i] = glm::vec2(d / len);
                break;
            }
        }
    }
    return out;
}

}  // namespace inkshade
