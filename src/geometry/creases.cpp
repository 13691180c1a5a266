// Creases and borders: one pass over the edges of the adjacency, in parallel blocks of edges
// whose lists are joined in edge order; the two face normals of each edge are computed on the
// spot. Convexity comes from which side of the first face's plane the second face's far vertex
// lies.
#include "geometry/creases.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
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

// Unit normal of face t, or zero for a zero-area face (normals.hpp). Computed per block of
// edges instead of read from a face_normals array: that would be 12 B a face (120 MB at 10 M
// triangles) beside the adjacency, at the peak of a first view.
glm::vec3 face_normal(const Mesh& mesh, const glm::uvec3& t) {
    return unit_normal(mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]);
}

// Classifies edges [first, last) into `out`.
void classify(const Mesh& mesh, const EdgeAdjacency& adjacency, double cos_limit, size_t first, size_t last,
              CreaseLines& out) {
    // The block's two-face edges use faces [lo, hi]. On a mesh whose face order follows its
    // vertex order that range is short, and each of its normals is computed once into `local`
    // instead of once for each of the face's three edges.
    uint32_t lo = EdgeAdjacency::kNoFace, hi = 0;
    for (size_t e = first; e < last; ++e)
        if (adjacency.flags[e] == 0) {
            lo = std::min(lo, adjacency.faces[e].x);
            hi = std::max(hi, adjacency.faces[e].y);
        }
    std::vector<glm::vec3> local;
    if (lo <= hi && hi - lo < 2 * (last - first)) {
        local.resize(hi - lo + 1);
        const size_t n = mesh.positions.size();
        for (uint32_t f = lo; f <= hi; ++f) {
            const glm::uvec3 t = mesh.triangles[f];
            if (t.x < n && t.y < n && t.z < n) local[f - lo] = face_normal(mesh, t);  // others are not read
        }
    }
    auto normal = [&](uint32_t f, const glm::uvec3& t) { return local.empty() ? face_normal(mesh, t) : local[f - lo]; };
    for (size_t e = first; e < last; ++e) {
        const glm::uvec2 edge = adjacency.edges[e];
        const glm::uvec2 faces = adjacency.faces[e];  // the two lowest
        LineSegment seg;
        seg.a = mesh.positions[edge.x];
        seg.b = mesh.positions[edge.y];
        seg.edge_a = vertex_key(edge.x);
        seg.edge_b = vertex_key(edge.y);
        seg.face = faces.x;
        if (adjacency.is_border(e)) {
            out.borders.push_back(seg);
            continue;
        }
        if (adjacency.is_non_manifold(e)) {
            out.non_manifold.push_back(seg);
            continue;
        }
        const glm::uvec3 t0 = mesh.triangles[faces.x], t1 = mesh.triangles[faces.y];
        const glm::dvec3 n0(normal(faces.x, t0));
        glm::dvec3 n1(normal(faces.y, t1));
        if (n0 == glm::dvec3(0.0) || n1 == glm::dvec3(0.0)) continue;  // zero-area face
        if (runs_forward(t0, edge.x, edge.y) == runs_forward(t1, edge.x, edge.y)) n1 = -n1;
        if (!(glm::dot(n0, n1) < cos_limit)) continue;  // fold at most the limit (or NaN)
        // Convex when the second face bends below the first face's plane (away from n0).
        const glm::dvec3 p = mesh.positions[edge.x];
        const glm::dvec3 far(mesh.positions[opposite(t1, edge.x, edge.y)]);
        (glm::dot(far - p, n0) <= 0.0 ? out.ridges : out.valleys).push_back(seg);
    }
}

}  // namespace

CreaseLines extract_creases(const Mesh& mesh, const EdgeAdjacency& adjacency, const CreaseOptions& options) {
    const double cos_limit = std::cos(glm::radians(double(options.angle_degrees)));
    // Fixed blocks (not TBB's adaptive ranges) so the joined lists do not depend on threads.
    constexpr size_t kBlock = size_t(1) << 16;
    const size_t edges = adjacency.edge_count(), blocks = (edges + kBlock - 1) / kBlock;
    std::vector<CreaseLines> parts(blocks);
    tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
        classify(mesh, adjacency, cos_limit, b * kBlock, std::min(edges, (b + 1) * kBlock), parts[b]);
    });
    CreaseLines out;
    auto join = [&](std::vector<LineSegment> CreaseLines::*list) {
        size_t total = 0;
        for (const CreaseLines& part : parts) total += (part.*list).size();
        (out.*list).reserve(total);
        for (const CreaseLines& part : parts)
            (out.*list).insert((out.*list).end(), (part.*list).begin(), (part.*list).end());
    };
    join(&CreaseLines::ridges);
    join(&CreaseLines::valleys);
    join(&CreaseLines::borders);
    join(&CreaseLines::non_manifold);
    return out;
}

}  // namespace inkshade::geometry
