// CPU twin of shaders/common/cell_hash.glsl (the one-word cell hash and voronoi's feature
// points) and of the Worley F1/F2 search and cell colours of shaders/shading/voronoi.frag, for
// reference values in the GL tests.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace inkshade::test {

// cell_hash.glsl's one-word cell hash: coordinates times kCellHashMul, xor-ed, lowbias32.
inline const glm::uvec3 kCellHashMul(0x8da6b343u, 0xd8163841u, 0xcb1ab31fu);
inline uint32_t cell_hash_mix(uint32_t h) {
    h ^= h >> 16u;
    h *= 0x7feb352du;
    h ^= h >> 15u;
    h *= 0x846ca68bu;
    h ^= h >> 16u;
    return h;
}
inline uint32_t cell_hash(glm::ivec3 c) {
    glm::uvec3 k = glm::uvec3(c) * kCellHashMul;
    return cell_hash_mix(k.x ^ k.y ^ k.z);
}
inline glm::vec3 cell_jitter(uint32_t h) {
    return glm::vec3(glm::ivec3(glm::uvec3(h >> 22u, h >> 12u, h >> 2u) & 1023u)) * (1.0f / 1024.0f);
}
inline glm::vec4 bytes_to_unit(uint32_t h) {
    return glm::vec4(glm::ivec4(glm::uvec4(h >> 24u, h >> 16u, h >> 8u, h) & 255u)) * (1.0f / 256.0f);
}
inline constexpr float kCellJitter = 0.3f;  // cell_hash.glsl's
inline glm::vec3 cell_offset(uint32_t h) { return (0.5f - kCellJitter) + (2.0f * kCellJitter) * cell_jitter(h); }

inline glm::vec3 cell_point(glm::ivec3 c) { return glm::vec3(c) + cell_offset(cell_hash(c)); }

struct Worley {
    float f1 = 1e9f, f2 = 1e9f;
    glm::ivec3 id{0};
};

// voronoi.frag's search: nearest and second-nearest feature points over the 2x2x2 cells whose
// centres surround x (cell units), with the shader's arithmetic.
inline Worley worley(const glm::vec3& x) {
    glm::ivec3 base(glm::floor(x - 0.5f));
    glm::vec3 xf = x - glm::vec3(base);
    float d1 = 1e18f, d2 = 1e18f;
    glm::ivec3 id = base;
    for (int k = 0; k <= 1; ++k)
        for (int j = 0; j <= 1; ++j)
            for (int i = 0; i <= 1; ++i) {
                glm::ivec3 o(i, j, k);
                glm::vec3 r = glm::vec3(o) + cell_offset(cell_hash(base + o)) - xf;
                float d = glm::dot(r, r);
                d2 = std::min(d2, std::max(d1, d));
                id = d < d1 ? base + o : id;
                d1 = std::min(d1, d);
            }
    return {std::sqrt(d1), std::sqrt(d2), id};
}

// voronoi.frag's cell_color.
inline glm::vec3 voronoi_cell_color(glm::ivec3 c) {
    glm::vec2 h = glm::vec2(bytes_to_unit(cell_hash_mix(cell_hash(c))));
    float a = 6.2831853f * h.x, ca = std::cos(a), sa = std::sin(a);
    glm::vec3 hue = 0.5f + 0.5f * glm::vec3(ca, -0.5f * ca - 0.8660254f * sa, -0.5f * ca + 0.8660254f * sa);
    return glm::mix(glm::vec3(0.15f), hue, 0.55f + 0.45f * h.y);
}

}  // namespace inkshade::test
