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

bool by_edge(const glm::uvec2& a, const glm::uvec2& b) { return a.x < b.x; }

}  // namespace

uint32_t EdgeAdjacency::face_count(size_t e) const {
    if (faces[e].y == kNoFace) return 1;
    if (!is_non_manifold(e)) return 2;
    const auto [first, last] =
        std::equal_range(more_faces.begin(), more_faces.end(), glm::uvec2(uint32_t(e), 0), by_edge);
    return 2 + uint32_t(last - first);
}

uint32_t EdgeAdjacency::face(size_t e, uint32_t k) const {
    if (k < 2) return faces[e][int(k)];
    return std::lower_bound(more_faces.begin(), more_faces.end(), glm::uvec2(uint32_t(e), 0), by_edge)[k - 2].y;
}

EdgeAdjacency build_edge_adjacency(const Mesh& mesh) {
    const auto& tris = mesh.triangles;
    const size_t n = mesh.positions.size();
    if (tris.size() > std::numeric_limits<uint32_t>::max() / 3)
        throw std::length_error("build_edge_adjacency: more than 1431655765 triangles");
    EdgeAdjacency adj;

    // Bucket sides by lower vertex (counting sort: count, prefix sum, fill in face order). The
    // counts sit two places up, so filling advances start[v + 1] from the start of bucket v to
    // its end, leaving start[v] = the start of bucket v without a second cursor array.
    std::vector<uint32_t> start(n + 2, 0);
    for (const glm::uvec3& t : tris)
        if (usable(t, n))
            for (int k = 0; k < 3; ++k) ++start[std::min(t[k], t[(k + 1) % 3]) + 2];
    for (size_t i = 2; i < start.size(); ++i) start[i] += start[i - 1];
    const uint32_t total = start[n + 1];
    auto upper = [&](uint32_t side) {
        const glm::uvec3 t = tris[side / 3];
        return std::max(t[side % 3], t[(side % 3 + 1) % 3]);
    };

    // Exact for a closed manifold mesh (two sides an edge).
    adj.edges.reserve(total / 2 + 1);
    adj.faces.reserve(total / 2 + 1);
    adj.flags.reserve(total / 2 + 1);
    // The buckets are filled and turned into edges a block of vertices at a time, each block
    // from its own pass over the faces: a quarter of the sides in memory at once (30 MB instead
    // of 120 at 10 M triangles, beside the adjacency being built) for three more cheap passes.
    const uint32_t block_sides = std::max<uint32_t>(total / 4 + 1, 1u << 22);
    // A side is stored as 3·face + slot (slot 0: (t0,t1), 1: (t1,t2), 2: (t2,t0)): four bytes
    // instead of twelve, since page faults on fresh memory dominate at a million faces.
    std::vector<uint32_t> sides;
    for (size_t v0 = 0; v0 < n;) {
        const uint32_t base = start[v0 + 1];  // the start of bucket v0 (nothing filled yet)
        size_t v1 = v0 + 1;                   // at least one vertex, however many sides it has
        while (v1 < n && start[v1 + 2] - base <= block_sides) ++v1;
        sides.resize(start[v1 + 1] - base);
        for (size_t f = 0; f < tris.size(); ++f) {
            const glm::uvec3 t = tris[f];
            if (!usable(t, n)) continue;
            for (uint32_t k = 0; k < 3; ++k) {
                const uint32_t lower = std::min(t[k], t[(k + 1) % 3]);
                if (lower >= v0 && lower < v1) sides[start[lower + 1]++ - base] = uint32_t(3 * f + k);
            }
        }
        for (size_t v = v0; v < v1; ++v) {
            const auto first = sides.begin() + (start[v] - base), last = sides.begin() + (start[v + 1] - base);
            // By (upper vertex, face, slot): a handful of entries per vertex.
            std::sort(first, last, [&](uint32_t a, uint32_t b) {
                const uint32_t ua = upper(a), ub = upper(b);
                return ua != ub ? ua < ub : a < b;
            });
            for (auto it = first; it != last;) {
                const uint32_t e = uint32_t(adj.edges.size()), j = upper(*it);
                adj.edges.emplace_back(uint32_t(v), j);
                auto run = it + 1;
                for (; run != last && upper(*run) == j; ++run)
                    if (run - it >= 2) adj.more_faces.emplace_back(e, *run / 3);
                const size_t count = size_t(run - it);
                adj.faces.emplace_back(*it / 3, count > 1 ? it[1] / 3 : EdgeAdjacency::kNoFace);
                adj.flags.push_back(uint8_t((count == 1 ? kEdgeBorder : 0) | (count > 2 ? kEdgeNonManifold : 0)));
                it = run;
            }
        }
        v0 = v1;
    }
    return adj;
}

}  // namespace inkshade::geometry
