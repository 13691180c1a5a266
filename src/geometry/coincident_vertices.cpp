#include "geometry/coincident_vertices.hpp"

#include <cstring>
#include <unordered_map>

namespace inkshade::geometry {

namespace {

struct PositionBits {
    uint32_t x, y, z;
    bool operator==(const PositionBits&) const = default;
};

struct PositionHash {
    size_t operator()(const PositionBits& p) const {
        return (size_t(p.x) * 73856093u) ^ (size_t(p.y) * 19349663u) ^ (size_t(p.z) * 83492791u);
    }
};

PositionBits bits_of(glm::vec3 p) {
    for (int k = 0; k < 3; ++k)
        if (p[k] == 0.0f) p[k] = 0.0f;  // -0 and +0 are one position
    PositionBits b;
    std::memcpy(&b.x, &p.x, 4);
    std::memcpy(&b.y, &p.y, 4);
    std::memcpy(&b.z, &p.z, 4);
    return b;
}

}  // namespace

std::vector<uint32_t> canonical_vertices(const Mesh& mesh) {
    const auto& p = mesh.positions;
    std::vector<uint32_t> canonical(p.size());
    std::unordered_map<PositionBits, uint32_t, PositionHash> first;
    first.reserve(p.size());
    for (size_t v = 0; v < p.size(); ++v) canonical[v] = first.try_emplace(bits_of(p[v]), uint32_t(v)).first->second;
    return canonical;
}

}  // namespace inkshade::geometry
