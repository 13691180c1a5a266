// Cast shadows (line type `cast-shadow`): the boundaries of the shadows the key light casts
// onto surfaces, by ray casting towards the light. Whether a point is in cast shadow is asked of
// the mesh's ray scene at every vertex that faces the light (n·l > 0); on each mesh edge whose
// two ends disagree the boundary is found by bisection along the edge, and a face with two such
// edges gives the segment between them. The attached shadow (n·l ≤ 0, past the terminator) is
// not a cast shadow: it is `light-contour`'s, and faces with a corner there give no segment.
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

class RayScene;

// Bisection along an edge stops when the bracket is shorter than this fraction of the edge
// (2^-20: far below a pixel for any edge the image shows).
constexpr int kCastShadowBisections = 20;

// Is p, a point of the mesh facing the light, in the shadow of some surface? A ray from p
// towards the light (`light`: a directional light's direction, a point light's position, the
// ray ending there) meets a face. Hits closer than `skip` (world units) are the point's own
// faces. A hit that leaves a solid (its face turned towards the light) within `acne` of p is
// the point's own surface curving past the ray on a coarse mesh — the ray went in under a face
// whose vertex normal faces the light — and does not count; farther away it does (an open
// sheet seen from behind casts its shadow too).
bool in_cast_shadow(const RayScene& scene, const Mesh& mesh, const Light& light, const glm::vec3& p, double skip,
                    double acne);

// The segments of the cast-shadow boundaries, in face order (parallel over faces,
// deterministic): each end on a mesh edge keyed edge_key(i, j), its point bisected from the
// edge alone (from the lower to the higher index) so the two faces of an edge share it bit for
// bit and the segments chain. Strength 1. Limits: the boundary is straight across a face, a
// shadow crossing an edge twice or lying inside one face is missed, and the shadow of a
// surface within `acne` (twice the longest edge at the point) of a point that leaves a solid
// there is not seen. `normals`: one unit vertex normal per vertex (std::invalid_argument
// otherwise). Faces with an out-of-range or repeated index give none.
std::vector<LineSegment> extract_cast_shadows(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                              const Light& light, const RayScene& scene);

}  // namespace inkshade::geometry
