#include "io/gltf_rest_pose.hpp"

#include <cmath>

namespace inkshade::io {

glm::dquat rotation_of(const glm::dmat4& m) {
    glm::dvec3 c0(m[0]), c1(m[1]), c2(m[2]);
    double sx = glm::length(c0);
    const double sy = glm::length(c1), sz = glm::length(c2);
    if (glm::determinant(glm::dmat3(m)) < 0.0) sx = -sx;
    if (sx == 0.0 || sy == 0.0 || sz == 0.0 || !std::isfinite(sx * sy * sz)) return glm::dquat(1.0, 0.0, 0.0, 0.0);
    const glm::dquat q = glm::quat_cast(glm::dmat3(c0 / sx, c1 / sy, c2 / sz));
    const double len = glm::length(q);
    return len > 0.0 ? q / len : glm::dquat(1.0, 0.0, 0.0, 0.0);
}

}  // namespace inkshade::io
