// Intersection lines (line type `intersection`): where two surfaces of one mesh cross — the
// parts of an assembly, hair through a head, a self-intersecting sheet — as Blender's Line Art
// draws them. They depend on the mesh alone, not on the view.
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// One segment per pair of crossing triangles (f, g), f < g, that share no vertex, sorted by
// (face, face_b) = (f, g), whatever the thread count. A segment runs between the two points
// where an edge of one triangle pierces the other; each end's key is pierce_key(id), id
// numbering the distinct (edge, pierced face) pairs in the order of (edge_key, face), so the
// segments of the faces on either side of an edge meet at the same key and at bit-identical
// points there (chain_segments joins them into polylines). The point is computed in double
// from that pair alone, the edge taken from its lower to its higher vertex index. Two other
// kinds of node: where the crossing passes exactly through a vertex v, (vertex_key(v), face),
// shared by every face around v; where two faces have a vertex each at the same point (two
// parts tessellated alike that meet there), (edge_key(v, w), kNoFace) for those vertices, the
// end of the two segments that run from that point. Strength 1.
//
// Limits:
// - Pairs sharing a vertex are skipped, as Line Art does (neighbouring faces meet along their
//   shared edge anyway): a surface crossing a face it shares a vertex with — a fold of a
//   coarse sheet through its own neighbour — has no line there. Pairs with two vertices at
//   the same points (the seams of an unwelded mesh) are skipped too, and on an unwelded mesh
//   a line breaks where it crosses a seam (the two sides have different edges).
// - Coplanar pairs give nothing, and surfaces that only touch (a face resting on another, an
//   edge lying in another face's plane, a vertex touching a face) give no line or pieces of
//   one. An exact zero is decided by one rule everywhere (a vertex in the plane of a face
//   counts as on its front side; a point exactly on an edge as inside the face on one side of
//   that edge), so a crossing through a vertex or through an edge still chains; where several
//   zeros meet (a crossing running exactly along a mesh edge, or through a vertex lying
//   exactly on the other surface's edge) the line may break.
// - A pair whose test does not come out as exactly two pierce points (rounding in nearly
//   degenerate configurations) gives no segment, a gap in its line.
// Faces with an out-of-range or repeated index, a non-finite position or zero area are
// ignored.
std::vector<LineSegment> extract_intersections(const Mesh& mesh);

}  // namespace inkshade::geometry
