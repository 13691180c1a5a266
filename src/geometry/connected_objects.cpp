#include "geometry/connected_objects.hpp"

#include <numeric>

#include "geometry/coincident_vertices.hpp"

namespace inkshade::geometry {

namespace {

// Union-find over vertices with path halving; the root is the lowest vertex of its set.
uint32_t find(std::vector<uint32_t>& parent, uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

void unite(std::vector<uint32_t>& parent, uint32_t a, uint32_t b) {
    a = find(parent, a), b = find(parent, b);
    if (a < b) parent[b] = a;
    if (b < a) parent[a] = b;
}

}  // namespace

std::vector<uint32_t> face_objects(const Mesh& mesh) {
    const size_t n = mesh.positions.size();
    std::vector<uint32_t> parent = canonical_vertices(mesh);  // coincident vertices start joined
    const auto valid = [n](const glm::uvec3& t) { return t.x < n && t.y < n && t.z < n; };
    for (const glm::uvec3& t : mesh.triangles)
        if (valid(t)) unite(parent, t.x, t.y), unite(parent, t.y, t.z);
    std::vector<uint32_t> objects(mesh.triangles.size(), kNoObject);
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        if (valid(mesh.triangles[f])) objects[f] = find(parent, mesh.triangles[f].x);
    return objects;
}

}  // namespace inkshade::geometry
