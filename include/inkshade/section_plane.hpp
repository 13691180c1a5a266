// A plane cutting the model (--section-plane), drawn by the line type `clip-boundary`.
#pragma once
#include <glm/glm.hpp>

namespace inkshade {

// The plane through `point` with unit `normal`; the side the normal points to is the one cut
// away.
struct SectionPlane {
    glm::vec3 point{0.0f};
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    // Signed distance of p from the plane, positive on the side cut away.
    double distance(const glm::vec3& p) const {
        return glm::dot(glm::dvec3(p) - glm::dvec3(point), glm::dvec3(normal));
    }
};

}  // namespace inkshade
