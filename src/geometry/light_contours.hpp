// Light contours (line type `light-contour`): where the key light grazes the surface, the zero
// set of n·l with n the vertex normals interpolated across faces, found on mesh edges as the
// occluding contour finds n·v = 0 (contours.hpp). l is the light's direction for a directional
// light; for a point (or spot) light l = l_pos − p, whose zero set is where the cone from the
// light touches the surface.
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// n·l per vertex: l the unit vector towards a directional light, l_pos − p for a point or spot
// light (its sign is what counts: not normalised, it is linear in p); non-finite
// values become 0. Throws std::invalid_argument unless there is one normal per vertex.
std::vector<float> light_dot_normal(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Light& light);

// The segments of n·l = 0 (extract_isolines at level 0: strength 1, face order, the lit side
// on the left of a → b).
std::vector<LineSegment> extract_light_contours(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                                const Light& light);

}  // namespace inkshade::geometry
