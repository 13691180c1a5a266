// Where a plane cuts the mesh (line type `clip-boundary`): the zero set of the signed distance
// to the plane, linear along each edge, so the segments are exact and, on a closed mesh, chain
// into closed loops (the cut's outlines). The planes are the camera's near plane and the user's
// section plane (SectionPlane, --section-plane).
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/contours.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/mesh.hpp"
#include "inkshade/section_plane.hpp"

namespace inkshade::geometry {

// The near plane as a SectionPlane: through the point `near_plane` in front of the eye, its
// normal towards the eye (what GL clips away lies on the normal's side).
SectionPlane near_plane_of(const Camera& camera);

// The segments of distance(p) = 0 (extract_isolines at level 0) with `isoline` set, so cuts by
// different planes crossing one edge do not chain together. Faces with a non-finite distance
// give none.
std::vector<LineSegment> extract_plane_cut(const Mesh& mesh, const SectionPlane& plane, uint32_t isoline);

}  // namespace inkshade::geometry
