// Mesh member functions.
#include "inkshade/mesh.hpp"

namespace inkshade {

// Axis-aligned box over all positions (referenced or not); a zero box for an empty mesh so
// callers can always take center() and diagonal().
BoundingBox Mesh::bounds() const {
    BoundingBox box;
    if (positions.empty()) return box;
    box.min = box.max = positions.front();
    for (const glm::vec3& p : positions) {
        box.min = glm::min(box.min, p);
        box.max = glm::max(box.max, p);
    }
    return box;
}

}  // namespace inkshade
