// Occluding contours of a mesh with hard edges (Mesh::has_hard_edges). n·v is taken per
// shading normal, so a flat face has no crossing inside it (averaged normals would draw a cube's
// "contour" as a polygon across its faces), and where a hard edge has one face turned to the
// viewer and the other away, the edge itself is the contour: a cube's outline runs along its
// edges, as the silhouette of a polyhedron does.
#pragma once
#include <vector>

#include "geometry/contours.hpp"

namespace inkshade::geometry {

// Contour segments (strength 1): first the zero crossings of n·v inside faces, in face order,
// then the pieces of hard edges (edges of exactly two faces whose shading normals differ at an
// end) along which the two faces' n·v differ in sign, in edge order. Crossing ends are keyed by
// the edge's two shading normal ids (edge_key), so they chain across smooth edges and meet the
// hard-edge piece that continues them; hard-edge pieces end at vertices with vertex_key. Front
// side on the left of a → b, as extract_contours. Faces with an out-of-range index or shading
// normal id give nothing. Requires mesh.has_hard_edges().
std::vector<LineSegment> extract_hard_edge_contours(const Mesh& mesh, const Camera& camera);

}  // namespace inkshade::geometry
