#include "geometry/material_boundaries.hpp"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <tuple>

#include "geometry/coincident_vertices.hpp"

namespace inkshade::geometry {

namespace {

struct EdgeUse {
    uint64_t key;  // edge_key of the canonical ends
    uint32_t material;
    uint32_t face;
    bool operator<(const EdgeUse& o) const {
        return std::tie(key, material, face) < std::tie(o.key, o.material, o.face);
    }
};

bool several_materials(const Mesh& mesh) {
    const auto& m = mesh.face_materials;
    return m.size() == mesh.triangles.size() && !m.empty() &&
           std::any_of(m.begin(), m.end(), [&](uint32_t id) { return id != m[0]; });
}

}  // namespace

std::vector<LineSegment> extract_material_boundaries(const Mesh& mesh) {
    if (!several_materials(mesh)) return {};
    const std::vector<uint32_t> canonical = canonical_vertices(mesh);
    const size_t n = mesh.positions.size();
    std::vector<EdgeUse> uses;
    uses.reserve(3 * mesh.triangles.size());
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        const glm::uvec3 t = mesh.triangles[f];
        if (t.x >= n || t.y >= n || t.z >= n) continue;
        const glm::uvec3 c(canonical[t.x], canonical[t.y], canonical[t.z]);
        if (c.x == c.y || c.y == c.z || c.z == c.x) continue;
        for (int e = 0; e < 3; ++e)
            uses.push_back({edge_key(c[e], c[(e + 1) % 3]), mesh.face_materials[f], uint32_t(f)});
    }
    tbb::parallel_sort(uses.begin(), uses.end());
    std::vector<LineSegment> out;
    for (size_t i = 0; i < uses.size();) {
        size_t j = i;
        uint32_t lowest_face = uses[i].face;
        for (; j < uses.size() && uses[j].key == uses[i].key; ++j) lowest_face = std::min(lowest_face, uses[j].face);
        // Sorted by material within the edge: two materials when the first and last differ.
        if (uses[j - 1].material != uses[i].material) {
            const uint32_t a = uint32_t(uses[i].key >> 32), b = uint32_t(uses[i].key);
            out.push_back({.a = mesh.positions[a],
                           .b = mesh.positions[b],
                           .edge_a = vertex_key(a),
                           .edge_b = vertex_key(b),
                           .face = lowest_face});
        }
        i = j;
    }
    return out;
}

}  // namespace inkshade::geometry
