// Mesh edges and the faces around each: the topology creases, borders and non-manifold checks
// need (line types `crease` and `border`, docs/lines.md).
#pragma once
#include <cstdint>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// Per-edge flags: a border edge has one face, a non-manifold edge more than two.
enum EdgeFlag : uint8_t { kEdgeBorder = 1, kEdgeNonManifold = 2 };

// Undirected edges: edge e joins edges[e].x < edges[e].y and is used by face_count(e) faces,
// face(e, 0) < face(e, 1) < …. Edges are sorted by (v0, v1), so the layout depends only on the
// mesh, never on the thread count. The first two faces are stored inline (faces[e], .y =
// kNoFace on a border): nearly every edge of a mesh has two, so an offset array would cost
// 4 B an edge for nothing (60 MB at 10 M triangles).
struct EdgeAdjacency {
    static constexpr uint32_t kNoFace = 0xffffffffu;

    std::vector<glm::uvec2> edges;
    std::vector<glm::uvec2> faces;  // the two lowest faces of each edge
    // (edge, face) for the third and later faces of non-manifold edges, sorted.
    std::vector<glm::uvec2> more_faces;
    std::vector<uint8_t> flags;  // EdgeFlag bits per edge

    size_t edge_count() const { return edges.size(); }
    uint32_t face_count(size_t e) const;
    uint32_t face(size_t e, uint32_t k) const;  // k < face_count(e)
    bool is_border(size_t e) const { return (flags[e] & kEdgeBorder) != 0; }
    bool is_non_manifold(size_t e) const { return (flags[e] & kEdgeNonManifold) != 0; }
    // Bytes of the four arrays' elements.
    size_t memory_bytes() const {
        return edges.size() * (sizeof(glm::uvec2) * 2 + sizeof(uint8_t)) + more_faces.size() * sizeof(glm::uvec2);
    }
};

// Builds the edge list in O(V + F): a counting sort by the lower vertex, then a sort of each
// vertex's few edges by (upper vertex, face). Faces with an out-of-range or repeated index have
// no edges (topologically degenerate); zero-area faces with three distinct indices are kept,
// since they still connect their neighbours. Throws std::length_error beyond 2³²/3 triangles.
EdgeAdjacency build_edge_adjacency(const Mesh& mesh);

}  // namespace inkshade::geometry
