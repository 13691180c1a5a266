// Creases and borders: one pass over the edges of the adjacency, face normals from normals.hpp.
// Convexity comes from which side of the first face's plane the second face's far vertex lies.
#include "geometry/creases.hpp"

#include <cmath>

#include "geometry/normals.hpp"

namespace inkshade::geometry {
namespace {

// The vertex of face t that is not on edge (v0, v1).
uint32_t opposite(const glm::uvec3& t, uint32_t v0, uint32_t v1) {
    for (int k = 0; k < 3; ++k)
        if (t[k] != v0 && t[k] != v1) return t[k];
    return t.x;  // not reached for faces in the adjacency (three distinct indices)
}

// True when face t traverses the edge as v0 → v1 (v0 immediately followed by v1).
bool runs_forward(const glm::uvec3& t, uint32_t v0, uint32_t v1) {
    for (int k = 0; k < 3; ++k)
        if (t[k] == v0) return t[(k + 1) % 3] == v1;
    return false;
}

}  // namespace

CreaseLines extract_creases(const Mesh& mesh, const EdgeAdjacency& adjacency,
                            const CreaseOptions& options) {
    const std::vector<glm::vec3> fn = face_normals(mesh);
    const double cos_limit = std::cos(glm::radians(double(options.angle_degrees)));
    CreaseLines out;
    for (size_t e = 0; e < adjacency.edge_count(); ++e) {
        const glm::uvec2 edge = adjacency.edges[e];
        const uint32_t* faces = adjacency.faces.data() + adjacency.face_offset[e];
        LineSegment seg;
        seg.a = mesh.positions[edge.x];
        seg.b = mesh.positions[edge.y];
        seg.edge_a = vertex_key(edge.x);
        seg.edge_b = vertex_key(edge.y);
        seg.face = faces[0];
        const uint32_t count = adjacency.face_count(e);
        if (count == 1) {
            out.borders.push_back(seg);
            continue;
        }
        if (count > 2) {
            out.non_manifold.push_back(seg);
            continue;
        }
        const glm::uvec3 t0 = mesh.triangles[faces[0]], t1 = mesh.triangles[faces[1]];
        const glm::dvec3 n0(fn[faces[0]]);
        glm::dvec3 n1(fn[faces[1]]);
        if (n0 == glm::dvec3(0.0) || n1 == glm::dvec3(0.0)) continue;  // zero-area face
        if (runs_forward(t0, edge.x, edge.y) == runs_forward(t1, edge.x, edge.y)) n1 = -n1;
        if (!(glm::dot(n0, n1) < cos_limit)) continue;  // fold at most the limit (or NaN)
        // Convex when the second face bends below the first face's plane (away from n0).
        const glm::dvec3 p = mesh.positions[edge.x];
        const glm::dvec3 far(mesh.positions[opposite(t1, edge.x, edge.y)]);
        (glm::dot(far - p, n0) <= 0.0 ? out.ridges : out.valleys).push_back(seg);
    }
    return out;
}

}  // namespace inkshade::geometry
