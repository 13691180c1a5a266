// The rotation that turns one unit vector onto another, as three.js r187 computes it
// (Quaternion.setFromUnitVectors, then normalize): spring bones and VRM node constraints must
// turn their bones exactly as three-vrm does, whose quaternions come from this function.
#pragma once
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace inkshade::io {

// For opposite vectors a half-turn about a perpendicular axis, chosen as three.js chooses it.
inline glm::dquat from_unit_vectors(const glm::dvec3& from, const glm::dvec3& to) {
    double r = glm::dot(from, to) + 1.0;
    glm::dquat q;
    if (r < 1e-8) {
        r = 0.0;
        q = std::abs(from.x) > std::abs(from.z) ? glm::dquat(r, -from.y, from.x, 0.0)
                                                : glm::dquat(r, 0.0, -from.z, from.y);
    } else {
        const glm::dvec3 c = glm::cross(from, to);
        q = glm::dquat(r, c.x, c.y, c.z);
    }
    const double len = glm::length(q);
    return len > 0.0 ? q / len : glm::dquat(1.0, 0.0, 0.0, 0.0);
}

}  // namespace inkshade::io
