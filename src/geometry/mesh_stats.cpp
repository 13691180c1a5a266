// Mesh topology facts. Edges and duplicate faces (geometry/duplicate_faces.hpp) are found by
// sorting packed keys (TBB parallel sort) rather than with node-based maps, so 10 M triangles
// take about a second; components use union-find with path halving and union by size (Tarjan
// 1975).
#include "inkshade/mesh_stats.hpp"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "geometry/duplicate_faces.hpp"

namespace inkshade {
namespace {

class UnionFind {
public:
    explicit UnionFind(size_t n) : parent_(n), size_(n, 1) { std::iota(parent_.begin(), parent_.end(), uint32_t(0)); }
    uint32_t find(uint32_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void unite(uint32_t a, uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return;
        if (size_[a] < size_[b]) std::swap(a, b);
        parent_[b] = a;
        size_[a] += size_[b];
    }

private:
    std::vector<uint32_t> parent_, size_;
};

}  // namespace

// Conventions: every face whose indices are in range contributes its (up to three) distinct
// undirected edges — a self-loop edge (a, a) of a face with a repeated index is not an edge —
// and counts in F; a face with an out-of-range index counts as degenerate and adds nothing
// else. So a closed, consistently meshed surface has 0 boundary edges and V - E + F = 2 - 2g.
MeshStats mesh_stats(const Mesh& mesh) {
    MeshStats s;
    const auto& p = mesh.positions;
    const size_t n = p.size();
    s.vertices = n;
    s.triangles = mesh.triangles.size();
    const double diag = mesh.bounds().diagonal();
    const double min_area = 1e-12 * diag * diag;

    std::vector<uint64_t> edges;
    edges.reserve(3 * mesh.triangles.size());
    // A face is a duplicate when an earlier face has the same vertex set. The earlier face of an
    // in-range duplicate is in range too, so counting flagged in-range faces counts among those.
    const std::vector<uint8_t> duplicate = geometry::find_duplicate_faces(mesh.triangles);
    std::vector<uint8_t> referenced(n, 0);
    UnionFind components(n);
    size_t valid_faces = 0;
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        const glm::uvec3& t = mesh.triangles[f];
        if (t.x >= n || t.y >= n || t.z >= n) {
            ++s.degenerate_faces;
            continue;
        }
        ++valid_faces;
        if (duplicate[f]) ++s.duplicate_faces;
        const glm::dvec3 a(p[t.x]), b(p[t.y]), c(p[t.z]);
        const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
        const bool repeated = t.x == t.y || t.y == t.z || t.x == t.z;
        if (repeated || !(area > 0.0) || area < min_area) ++s.degenerate_faces;

        std::array<uint32_t, 3> v{t.x, t.y, t.z};
        std::sort(v.begin(), v.end());
        const auto key = [](uint32_t lo, uint32_t hi) { return (uint64_t(lo) << 32) | hi; };
        if (v[0] != v[1]) edges.push_back(key(v[0], v[1]));
        if (v[1] != v[2]) edges.push_back(key(v[1], v[2]));
        if (v[0] != v[2]) edges.push_back(key(v[0], v[2]));
        for (uint32_t i : v) referenced[i] = 1;
        components.unite(t.x, t.y);
        components.unite(t.x, t.z);
    }

    // Runs of equal keys in the sorted edge list are one edge; the run length is its number of
    // incident faces.
    tbb::parallel_sort(edges.begin(), edges.end());
    for (size_t i = 0; i < edges.size();) {
        size_t j = i + 1;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        ++s.edges;
        if (j - i == 1) ++s.boundary_edges;
        if (j - i > 2) ++s.non_manifold_edges;
        i = j;
    }

    size_t referenced_count = 0;
    for (size_t v = 0; v < n; ++v) {
        if (!referenced[v]) continue;
        ++referenced_count;
        if (components.find(uint32_t(v)) == v) ++s.components;
    }
    s.unreferenced_vertices = n - referenced_count;
    s.euler_characteristic = long(referenced_count) - long(s.edges) + long(valid_faces);
    return s;
}

}  // namespace inkshade
