#include "geometry/light_contours.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>

#include "geometry/isolines.hpp"

namespace inkshade::geometry {

std::vector<float> light_dot_normal(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Light& light) {
    if (normals.size() != mesh.positions.size())
        throw std::invalid_argument("light_dot_normal: need one normal per vertex");
    std::vector<float> g(normals.size());
    // A point light's l = l_pos − p unnormalised: n·l is then linear in p where n is, and its
    // zero set on a sphere is exactly the circle of tangency (normalising moves it off).
    const bool directional = light.type == LightType::Directional;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, g.size(), 16384), [&](const auto& range) {
        for (size_t v = range.begin(); v != range.end(); ++v) {
            const glm::vec3 p = mesh.positions[v];
            const float d = glm::dot(normals[v], directional ? light.direction_to_light(p) : light.position - p);
            g[v] = std::isfinite(d) ? d : 0.0f;
        }
    });
    return g;
}

std::vector<LineSegment> extract_light_contours(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                                const Light& light) {
    return extract_isolines(mesh, light_dot_normal(mesh, normals, light), {0.0});
}

}  // namespace inkshade::geometry
