#include "render/welded_attributes.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <unordered_map>

namespace inkshade::render {

namespace {

struct PositionKey {
    uint32_t bits[3];
    bool operator==(const PositionKey& o) const { return std::memcmp(bits, o.bits, sizeof bits) == 0; }
};
struct PositionHash {
    size_t operator()(const PositionKey& k) const {
        uint64_t h = 1469598103934665603ull;
        for (uint32_t b : k.bits) h = (h ^ b) * 1099511628211ull;
        return size_t(h);
    }
};

PositionKey key_of(glm::vec3 p) {
    // +0.0 and -0.0 are the same position.
    for (int i = 0; i < 3; ++i)
        if (p[i] == 0.0f) p[i] = 0.0f;
    PositionKey k{};
    std::memcpy(k.bits, &p, sizeof k.bits);
    return k;
}

uint32_t find(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

}  // namespace

std::vector<uint32_t> position_classes(const Mesh& mesh) {
    std::vector<uint32_t> cls(mesh.positions.size());
    std::unordered_map<PositionKey, uint32_t, PositionHash> first;
    first.reserve(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        cls[i] = first.try_emplace(key_of(mesh.positions[i]), uint32_t(i)).first->second;
    return cls;
}

std::vector<glm::vec3> welded_vertex_normals(const Mesh& mesh) {
    const std::vector<uint32_t> cls = position_classes(mesh);
    const size_t n = mesh.positions.size();
    std::vector<glm::vec3> sum(n, glm::vec3(0.0f));
    for (const glm::uvec3& t : mesh.triangles) {
        if (t.x >= n || t.y >= n || t.z >= n) continue;
        const glm::vec3 p[3] = {mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]};
        const glm::vec3 face = glm::cross(p[1] - p[0], p[2] - p[0]);
        const float len = glm::length(face);
        if (!(len > 0.0f) || !std::isfinite(len)) continue;
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
            const float la = glm::length(a), lb = glm::length(b);
            if (!(la > 0.0f && lb > 0.0f)) continue;
            const float angle = std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0f, 1.0f));
            sum[cls[t[k]]] += angle * face / len;
        }
    }
    std::vector<glm::vec3> out(n);
    for (size_t i = 0; i < n; ++i) {
        const glm::vec3 s = sum[cls[i]];
        const float len = glm::length(s);
        // Isolated or degenerate: fall back to the render normal, else no extrusion direction.
        out[i] = len > 0.0f ? s / len : (i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0.0f));
    }
    return out;
}

std::vector<uint32_t> face_object_ids(const Mesh& mesh, std::vector<glm::uvec2>* parts) {
    const std::vector<uint32_t> cls = position_classes(mesh);
    const size_t n = mesh.positions.size();
    std::vector<uint32_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    for (const glm::uvec3& t : mesh.triangles) {
        if (t.x >= n || t.y >= n || t.z >= n) continue;
        uint32_t a = find(parent, cls[t.x]);
        for (uint32_t v : {t.y, t.z}) {
            uint32_t b = find(parent, cls[v]);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
            a = std::min(a, b);
        }
    }
    const bool per_face_material = mesh.face_materials.size() == mesh.triangles.size();
    std::unordered_map<uint64_t, uint32_t> ids, part_numbers;
    std::vector<uint32_t> out(mesh.triangles.size(), 0);
    if (parts) parts->clear();
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        const glm::uvec3 t = mesh.triangles[f];
        const uint64_t component = t.x < n ? find(parent, cls[t.x]) : uint64_t(n);
        const uint64_t material = per_face_material ? mesh.face_materials[f] : 0;
        const auto [it, added] = ids.try_emplace((component << 32) | material, uint32_t(ids.size() + 1));
        out[f] = it->second;
        if (parts && added) {
            const uint32_t part = part_numbers.try_emplace(component, uint32_t(part_numbers.size() + 1)).first->second;
            parts->push_back({part, uint32_t(material) + 1});
        }
    }
    return out;
}

}  // namespace inkshade::render
