// The faces around each vertex (its star), in face order: what auto-smooth walks to find the
// faces on either side of an edge without a mesh-wide edge table (a few faces a vertex,
// typically six, so a look-up is a short scan).
#pragma once
#include <cstdint>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// faces[offsets[v] .. offsets[v + 1]) are the faces with a corner at v, in face order; a face
// with a repeated index is listed once per corner there, consecutively. Triangles must index
// existing vertices.
struct VertexFaces {
    std::vector<uint32_t> offsets, faces;

    const uint32_t* begin(uint32_t v) const { return faces.data() + offsets[v]; }
    const uint32_t* end(uint32_t v) const { return faces.data() + offsets[v + 1]; }
};

VertexFaces vertex_faces(const Mesh& mesh);
// Only the stars of the vertices v with only[v] != 0 (one entry per vertex); the others are
// empty: what auto-smooth needs where few vertices are near a hard edge.
VertexFaces vertex_faces(const Mesh& mesh, const std::vector<uint8_t>& only);

// The faces other than `face` that have both v and w (v ≠ w): how many (distinct faces) and the
// first of them. On a manifold edge count is 1, on a border 0.
struct EdgeMate {
    uint32_t count = 0, face = 0;
};
EdgeMate edge_mate(const Mesh& mesh, const VertexFaces& vf, uint32_t face, uint32_t v, uint32_t w);

}  // namespace inkshade::geometry
