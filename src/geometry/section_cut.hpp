// What a section plane (--section-plane) removes from the line drawing: every layer's segments
// keep only their part on the plane's kept side, and the visibility rays see the mesh without
// the faces wholly on the removed side, so the cut and what lies behind the removed part show.
// The render's raster passes still draw the whole mesh (docs/lines.md, `clip-boundary`).
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "inkshade/mesh.hpp"
#include "inkshade/section_plane.hpp"

namespace inkshade::geometry {

// `mesh`'s positions and triangles with the faces whose three corners lie on the removed side
// (distance > tolerance) collapsed to one vertex, which no ray hits; face indices unchanged,
// positions padded for Embree (reserve_embree_padding).
Mesh section_ray_mesh(const Mesh& mesh, const SectionPlane& plane, double tolerance);

// Drops the segments, or their parts, farther than `tolerance` on the removed side; a segment
// cut by the plane ends at the crossing, with a key of its own (a free chain end), so the lines
// of the cut itself (distance 0) stay whole.
void clip_to_section(std::vector<LineSegment>& segments, const SectionPlane& plane, double tolerance);

}  // namespace inkshade::geometry
