// Mesh member functions.
#include "inkshade/mesh.hpp"

#include <algorithm>

namespace inkshade {

uint32_t ShadingSplits::fan(uint32_t slot, uint32_t f) const {
    const auto begin = corner_face.begin() + corner_start[slot], end = corner_face.begin() + corner_start[slot + 1];
    const auto at = std::lower_bound(begin, end, f);
    return at != end && *at == f ? corner_fan[size_t(at - corner_face.begin())] : 0;
}

size_t ShadingSplits::memory_bytes() const {
    return split.size() * sizeof(uint64_t) +
           (rank.size() + extra.size() + corner_start.size() + corner_face.size() + corner_fan.size()) *
               sizeof(uint32_t) +
           normals.size() * sizeof(glm::vec3);
}

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
