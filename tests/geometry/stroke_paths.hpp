// Image paths with known geometry for the stroke tests: straight lines, circles and squares
// sampled densely, with depth and strength filled in.
#pragma once
#include <cmath>
#include <vector>

#include "inkshade/line_drawing.hpp"

namespace inkshade::test {

// From a to b, one point every `step` pixels (the end included), depth and strength set.
inline LinePath straight_path(glm::vec2 a, glm::vec2 b, float step = 1.0f) {
    LinePath p;
    const float len = glm::length(b - a);
    const int n = std::max(1, int(std::lround(len / step)));
    for (int i = 0; i <= n; ++i) p.points.push_back(a + (b - a) * (float(i) / float(n)));
    p.depth.assign(p.points.size(), 0.5f);
    p.strength.assign(p.points.size(), 1.0f);
    return p;
}

// A closed circle of `count` points, counter-clockwise on screen (y down: angle measured from
// +x towards -y), starting at angle 0.
inline LinePath circle_path(glm::vec2 centre, float radius, int count) {
    LinePath p;
    p.closed = true;
    for (int i = 0; i < count; ++i) {
        const double a = 2.0 * 3.14159265358979323846 * i / count;
        p.points.emplace_back(centre.x + radius * float(std::cos(a)), centre.y - radius * float(std::sin(a)));
    }
    p.depth.assign(p.points.size(), 0.5f);
    p.strength.assign(p.points.size(), 1.0f);
    return p;
}

// A closed axis-aligned square from `corner` with side `side`, a point every pixel.
inline LinePath square_path(glm::vec2 corner, float side) {
    LinePath p;
    p.closed = true;
    const glm::vec2 c[4] = {corner, corner + glm::vec2(side, 0), corner + glm::vec2(side, side),
                            corner + glm::vec2(0, side)};
    const int per_side = int(side);
    for (int k = 0; k < 4; ++k)
        for (int i = 0; i < per_side; ++i) p.points.push_back(c[k] + (c[(k + 1) % 4] - c[k]) * (float(i) / per_side));
    p.depth.assign(p.points.size(), 0.5f);
    p.strength.assign(p.points.size(), 1.0f);
    return p;
}

inline double path_length(const LinePath& p) {
    double s = 0.0;
    for (size_t i = 1; i < p.points.size(); ++i) s += glm::length(glm::dvec2(p.points[i] - p.points[i - 1]));
    if (p.closed && p.points.size() > 1) s += glm::length(glm::dvec2(p.points.front() - p.points.back()));
    return s;
}

}  // namespace inkshade::test
