#include "geometry/stroke_color.hpp"

#include "geometry/path_arc_length.hpp"

namespace inkshade::geometry {

std::vector<glm::vec3> stroke_colors(const LinePath& path, ColorAlong along, glm::vec3 start, glm::vec3 end,
                                     const ViewDepthRange& depth) {
    const size_t n = path.points.size();
    std::vector<glm::vec3> c;
    if (along == ColorAlong::None) return c;
    c.reserve(n);
    const std::vector<double> s = arc_lengths(path);
    const double total = s.empty() ? 0.0 : s.back();
    for (size_t i = 0; i < n; ++i) {
        float t = 0.0f;
        if (along == ColorAlong::Depth)
            t = path.depth.size() == n ? depth.fraction(path.depth[i]) : 0.0f;
        else
            t = total > 0.0 ? float(s[i] / total) : 0.0f;
        c.push_back(glm::mix(start, end, t));
    }
    return c;
}

}  // namespace inkshade::geometry
