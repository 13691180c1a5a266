// Level sets of one per-vertex function at several values (isophotes, topographic lines): the
// function is interpolated linearly over each face, as the contour's n·v is, and each level
// crossing a face gives one segment there.
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// Segments of f = levels[k] for every k, in face order (levels by increasing value within a
// face; parallel over faces, deterministic). `levels` must be strictly increasing; a segment
// on level k has isoline = k, so that levels crossing the same mesh edge, which share its edge
// key, chain apart. A vertex with f = level counts as above it (as extract_contours counts
// g = 0 as positive), so a face has at most one segment per level, and the crossing on an edge
// is computed from that edge alone: the two faces of an edge get bit-identical points. Walking
// a → b keeps the higher values on the left (counter-clockwise side). Faces with an index out
// of range, a repeated index or a non-finite value give no segment. Strength 1. With `facing`
// (n·v per vertex, view_dot_normal), faces whose three corners face away (n·v ≤ 0) give none
// either: rtsc's back-face cull, which spares visibility the lines on the far side. Throws
// std::invalid_argument when f (or facing) does not have one value per vertex.
std::vector<LineSegment> extract_isolines(const Mesh& mesh, const std::vector<float>& f,
                                          const std::vector<double>& levels,
                                          const std::vector<float>* facing = nullptr);

// The unit world vector of `direction` given in the camera's frame (x right, y up, z towards
// the viewer: OpenGL eye space, Camera::view()), as rtsc turns its light with the camera.
// Throws InputError naming `what` when direction has no length.
glm::dvec3 camera_to_world(const Camera& camera, const glm::dvec3& direction, const char* what);

}  // namespace inkshade::geometry
