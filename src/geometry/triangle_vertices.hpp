// Tests on a triangle's vertex indices that the visibility pieces share (ray_scene.cpp,
// occlusion_levels.cpp, edge_neighbours.cpp, visibility.cpp): what a face contains, and whether
// it may be used at all.
#pragma once
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace inkshade::geometry {

inline bool has_vertex(const glm::uvec3& t, uint32_t v) { return t.x == v || t.y == v || t.z == v; }

// Does triangle t index only vertices below nv? (Other triangles are never hit nor walked.)
inline bool in_range(const glm::uvec3& t, size_t nv) { return t.x < nv && t.y < nv && t.z < nv; }

inline int shared_vertices(const glm::uvec3& t, const glm::uvec3& u) {
    return int(has_vertex(t, u.x)) + int(has_vertex(t, u.y)) + int(has_vertex(t, u.z));
}

}  // namespace inkshade::geometry
