// CPU twin of shaders/common/cell_hash.glsl (pcg3d, Jarzynski & Olano 2020) and of the
// Worley F1/F2 search of shaders/shading/voronoi.frag, for reference values in the GL tests.
#pragma once
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace inkshade::test {

inline glm::uvec3 pcg3d(glm::uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

inline glm::vec3 hash_to_unit(glm::uvec3 h) { return glm::vec3(h >> 8u) * (1.0f / 16777216.0f); }

inline glm::vec3 cell_point(glm::ivec3 c) { return glm::vec3(c) + hash_to_unit(pcg3d(glm::uvec3(c))); }

struct Worley {
    float f1 = 1e9f, f2 = 1e9f;
    glm::ivec3 id{0};
};

// Nearest and second-nearest feature points over the 3x3x3 cells around x (cell units).
inline Worley worley(const glm::vec3& x) {
    Worley w;
    glm::ivec3 base(glm::floor(x));
    for (int k = -1; k <= 1; ++k)
        for (int j = -1; j <= 1; ++j)
            for (int i = -1; i <= 1; ++i) {
                glm::ivec3 c = base + glm::ivec3(i, j, k);
                float d = glm::distance(x, cell_point(c));
                if (d < w.f1) {
                    w.f2 = w.f1;
                    w.f1 = d;
                    w.id = c;
                } else if (d < w.f2) {
                    w.f2 = d;
                }
            }
    return w;
}

// voronoi.frag's cell_color.
inline glm::vec3 voronoi_cell_color(glm::ivec3 c) {
    glm::vec3 h = hash_to_unit(pcg3d(pcg3d(glm::uvec3(c))));
    glm::vec3 hue = 0.5f + 0.5f * glm::cos(6.2831853f * (h.x + glm::vec3(0.0f, 0.333333f, 0.666667f)));
    return glm::mix(glm::vec3(0.15f), hue, 0.55f + 0.45f * h.y);
}

}  // namespace inkshade::test
