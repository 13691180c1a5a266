// Edge adjacency by a counting sort on the lower vertex of each face side: every side lands in
// its vertex's bucket, each bucket (a vertex's degree, a handful of entries) is sorted, and
// runs of equal upper vertex become one edge. Linear in the mesh size and fully deterministic.
#include "geometry/adjacency.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace inkshade::geometry {
namespace {

bool usable(const glm::uvec3& t, size_t n) {
    return t.x < n && t.y < n && t.z < n && t.x != t.y && t.y != t.z && t.z != t.x;
}

}  // namespace

EdgeAdjacency build_edge_adjacency(const Mesh& mesh) {
    const auto& tris = mesh.triangles;
    const size_t n = mesh.positions.size();
    if (tris.size() > std::numeric_limits<uint32_t>::max() / 3)
        throw std::length_error("build_edge_adjacency: more than 1431655765 triangles");
    EdgeAdjacency adj;
    adj.face_edges.assign(tris.size(), glm::uvec3(EdgeAdjacency::kNoEdge));

    // Bucket sides by lower vertex (counting sort: count, prefix sum, fill in face order).
    std::vector<uint32_t> start(n + 1, 0);
    for (const glm::uvec3& t : tris)
        if (usable(t, n))
            for (int k = 0; k < 3; ++k) ++start[std::min(t[k], t[(k + 1) % 3]) + 1];
    for (size_t v = 0; v < n; ++v) start[v + 1] += start[v];
    // A side is stored as 3·face + slot (slot 0: (t0,t1), 1: (t1,t2), 2: (t2,t0)): four bytes
    // instead of twelve, since page faults on fresh memory dominate at a million faces.
    std::vector<uint32_t> sides(start[n]);
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (size_t f = 0; f < tris.size(); ++f) {
        const glm::uvec3 t = tris[f];
        if (!usable(t, n)) continue;
        for (uint32_t k = 0; k < 3; ++k)
            sides[fill[std::min(t[k], t[(k + 1) % 3])]++] = uint32_t(3 * f + k);
    }
    auto upper = [&](uint32_t side) {
        const glm::uvec3 t = tris[side / 3];
        return std::max(t[side % 3], t[(side % 3 + 1) % 3]);
    };

    adj.edges.reserve(sides.size() / 2 + 1);
    adj.flags.reserve(sides.size() / 2 + 1);
    adj.face_offset.reserve(sides.size() / 2 + 2);
    adj.face_offset.push_back(0);
    adj.faces.reserve(sides.size());
    for (size_t v = 0; v < n; ++v) {
        const auto first = sides.begin() + start[v], last = sides.begin() + start[v + 1];
        // By (upper vertex, face, slot): a handful of entries per vertex.
        std::sort(first, last, [&](uint32_t a, uint32_t b) {
            const uint32_t ua = upper(a), ub = upper(b);
            return ua != ub ? ua < ub : a < b;
        });
        for (auto it = first; it != last;) {
            const uint32_t e = uint32_t(adj.edges.size()), j = upper(*it);
            adj.edges.emplace_back(uint32_t(v), j);
            auto run = it;
            for (; run != last && upper(*run) == j; ++run) {
                adj.faces.push_back(*run / 3);
                adj.face_edges[*run / 3][*run % 3] = e;
            }
            adj.face_offset.push_back(uint32_t(adj.faces.size()));
            const size_t count = size_t(run - it);
            adj.flags.push_back(uint8_t((count == 1 ? kEdgeBorder : 0) |
                                        (count > 2 ? kEdgeNonManifold : 0)));
            it = run;
        }
    }
    return adj;
}

}  // namespace inkshade::geometry
