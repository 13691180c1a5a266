// Mesh edges and the faces around each: the topology creases, borders and non-manifold checks
// need (SPEC §3 `crease`, `border`).
#pragma once
#include <cstdint>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// Per-edge flags: a border edge has one face, a non-manifold edge more than two.
enum EdgeFlag : uint8_t { kEdgeBorder = 1, kEdgeNonManifold = 2 };

// Undirected edges in compressed form: edge e joins edges[e].x < edges[e].y and is used by
// faces[face_offset[e] .. face_offset[e + 1]) (ascending face index). Edges are sorted by
// (v0, v1), so the layout depends only on the mesh, never on the thread count.
struct EdgeAdjacency {
    static constexpr uint32_t kNoEdge = 0xffffffffu;

    std::vector<glm::uvec2> edges;
    std::vector<uint32_t> face_offset;  // edges.size() + 1 entries
    std::vector<uint32_t> faces;
    std::vector<uint8_t> flags;  // EdgeFlag bits per edge
    // Per triangle, the edge ids of its sides (t0,t1), (t1,t2), (t2,t0); kNoEdge for a skipped
    // face, so a face's neighbours are found without a search.
    std::vector<glm::uvec3> face_edges;

    size_t edge_count() const { return edges.size(); }
    uint32_t face_count(size_t e) const { return face_offset[e + 1] - face_offset[e]; }
    bool is_border(size_t e) const { return (flags[e] & kEdgeBorder) != 0; }
    bool is_non_manifold(size_t e) const { return (flags[e] & kEdgeNonManifold) != 0; }
};

// Builds the edge list in O(V + F): a counting sort by the lower vertex, then a sort of each
// vertex's few edges by (upper vertex, face). Faces with an out-of-range or repeated index have
// no edges (topologically degenerate); zero-area faces with three distinct indices are kept,
// since they still connect their neighbours. Throws std::length_error beyond 2³²/3 triangles.
EdgeAdjacency build_edge_adjacency(const Mesh& mesh);

}  // namespace inkshade::geometry
