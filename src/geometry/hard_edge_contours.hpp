// Occluding contours of a mesh with hard edges (Mesh::has_hard_edges). n·v is taken per
// shading normal, so a flat face has no crossing inside it (averaged normals would draw a cube's
// "contour" as a polygon across its faces), and where a hard edge has one face turned to the
// viewer and the other away, the edge itself is the contour: a cube's outline runs along its
// edges, as the silhouette of a polyhedron does.
#pragma once
#include <array>
#include <vector>

#include "geometry/contours.hpp"

namespace inkshade::geometry {

// One end of an edge as a face sees it: its vertex and that face's shading normal there.
struct ShadingCorner {
    uint32_t vertex, normal;
};

// An edge as one face walks it: from `from` to `to` in the face's counter-clockwise order.
struct HardEdgeSide {
    uint64_t key;  // edge_key of the two vertices
    uint32_t face;
    ShadingCorner from, to;
};

// What the contour needs of a mesh's hard edges, whatever the view: the hard edges (edges of
// exactly two faces whose shading normals differ at an end) with their two sides, sorted by
// (key, face). Built once per mesh from the faces at split vertices (ShadingSplits); its size
// grows with the hard edges.
struct HardEdgeTable {
    std::vector<std::array<HardEdgeSide, 2>> edges;

    size_t memory_bytes() const { return edges.size() * sizeof(edges[0]); }
};
HardEdgeTable hard_edge_table(const Mesh& mesh);

// Contour segments (strength 1): first the zero crossings of n·v inside faces, in face order,
// then the pieces of hard edges along which the two faces' n·v differ in sign, in edge order.
// Crossing ends are keyed by the edge's two shading normal ids (edge_key), so they chain across
// smooth edges and meet the hard-edge piece that continues them; hard-edge pieces end at
// vertices with vertex_key. Front side on the left of a → b, as extract_contours. Faces with an
// out-of-range index or shading normal id give nothing. Per view this costs what
// extract_contours does plus a few operations per hard edge. Requires mesh.has_hard_edges(),
// and `table` built from this mesh.
std::vector<LineSegment> extract_hard_edge_contours(const Mesh& mesh, const HardEdgeTable& table, const Camera& camera);
// The same, building the table first.
std::vector<LineSegment> extract_hard_edge_contours(const Mesh& mesh, const Camera& camera);

}  // namespace inkshade::geometry
