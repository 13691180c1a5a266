// A line point's own neighbourhood (docs/lines.md, Visibility): the surface around the point
// that belongs to the point's own sheet of the mesh, which may pass a little in front of it
// without hiding it (RayScene::occlusion_levels).
#pragma once
#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace inkshade::geometry {

// The faces within `radius` of p (closest-point distance, from an Embree point query on
// `scene`) that are joined to a face for which own(face) holds (the faces that contain p)
// through mesh vertices and edges that come within that radius of p, each shared by two faces
// within it. Sorted. At most `limit` faces of the
// ball are looked at (a ball of more faces is cut there: fewer faces are p's own, so more
// surface hides it, never less).
template <class Own>
std::vector<uint32_t> own_neighbourhood(RTCScene scene, const glm::uvec3* triangles, const glm::vec3* positions,
                                        const glm::vec3& p, float radius, Own&& own, size_t limit = 256);

// The faces within `radius` of p (at most `limit`), unsorted.
std::vector<uint32_t> faces_near(RTCScene scene, const glm::uvec3* triangles, const glm::vec3* positions,
                                 const glm::vec3& p, float radius, size_t limit);

// Of `faces`, those joined to one with seed[i] set across shared vertices and edges within
// `radius` of p, sorted.
std::vector<uint32_t> connected_to_seeds(const glm::uvec3* triangles, const glm::vec3* positions,
                                         const std::vector<uint32_t>& faces, const std::vector<char>& seed,
                                         const glm::vec3& p, float radius);

// Do faces f and g share a vertex or an edge that comes within `radius` of p? (Then, when g
// contains p and f comes within the radius, f is in p's own neighbourhood: no query needed.)
bool joined(const glm::uvec3* triangles, const glm::vec3* positions, uint32_t f, uint32_t g, const glm::vec3& p,
            float radius);

template <class Own>
std::vector<uint32_t> own_neighbourhood(RTCScene scene, const glm::uvec3* triangles, const glm::vec3* positions,
                                        const glm::vec3& p, float radius, Own&& own, size_t limit) {
    const std::vector<uint32_t> ball = faces_near(scene, triangles, positions, p, radius, limit);
    std::vector<char> seed(ball.size());
    for (size_t i = 0; i < ball.size(); ++i) seed[i] = own(ball[i]) ? 1 : 0;
    return connected_to_seeds(triangles, positions, ball, seed, p, radius);
}

}  // namespace inkshade::geometry
