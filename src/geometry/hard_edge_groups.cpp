#include "geometry/hard_edge_groups.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace inkshade::geometry {

void drop_small_hard_edge_groups(const Mesh& mesh, std::vector<uint8_t>& flags, size_t min_edges) {
    // The hard edges once each (an edge of two faces is flagged in both), as vertex pairs.
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    for (size_t f = 0; f < flags.size() && f < mesh.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k)
            if (flags[f] >> k & 1) {
                const uint32_t a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
                edges.emplace_back(std::min(a, b), std::max(a, b));
            }
    if (edges.empty()) return;
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

    // Groups by union-find over the hard edges' vertices only (numbered densely).
    std::unordered_map<uint32_t, uint32_t> node;
    auto node_of = [&](uint32_t v) { return node.try_emplace(v, uint32_t(node.size())).first->second; };
    std::vector<std::pair<uint32_t, uint32_t>> ends(edges.size());
    for (size_t e = 0; e < edges.size(); ++e) ends[e] = {node_of(edges[e].first), node_of(edges[e].second)};
    std::vector<uint32_t> parent(node.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&](uint32_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    for (const auto& [a, b] : ends) parent[root(a)] = root(b);
    std::vector<uint32_t> size(node.size(), 0);
    for (const auto& [a, b] : ends) ++size[root(a)];
    // A small group is kept when it spans a tenth of the model: a tetrahedron's six edges.
    std::vector<BoundingBox> extent(node.size(), {glm::vec3(INFINITY), glm::vec3(-INFINITY)});
    for (const auto& [v, i] : node) {
        BoundingBox& b = extent[root(i)];
        b.min = glm::min(b.min, mesh.positions[v]);
        b.max = glm::max(b.max, mesh.positions[v]);
    }
    const float wide = 0.1f * mesh.bounds().diagonal();
    std::vector<uint8_t> keep(node.size(), 0);
    for (uint32_t i = 0; i < keep.size(); ++i)
        if (root(i) == i) keep[i] = size[i] >= min_edges || extent[i].diagonal() >= wide;

    for (size_t f = 0; f < flags.size() && f < mesh.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k)
            if ((flags[f] >> k & 1) && !keep[root(node.at(mesh.triangles[f][k]))]) flags[f] &= uint8_t(~(1u << k));
}

}  // namespace inkshade::geometry
