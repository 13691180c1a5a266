// A torus knot of 4096 × 128 quads (1,048,576 triangles) with every vertex moved along its
// normal by up to ±0.2 % of the tube radius (a deterministic hash, like scanner noise), normals
// recomputed: the scan stand-in of the curvature and visibility benchmarks. With
// INKSHADE_BENCH_SCAN=FILE both measure that file instead, loaded as `inkshade lines` loads it
// (default settings: auto-smooth at 30°), so a real scan's view and curvature are timed in one
// run and their ratio read from it (docs/benchmarks.md).
#pragma once
#include <cstdint>
#include <cstdlib>

#include "geometry/builtin_models.hpp"
#include "geometry/normals.hpp"
#include "inkshade/io.hpp"

namespace inkshade::bench {

inline const Mesh& noisy_knot() {
    static const Mesh mesh = [] {
        if (const char* file = std::getenv("INKSHADE_BENCH_SCAN"); file && *file) return load_mesh(file);
        const float tube = 0.15f;
        Mesh m = builtin::torus_knot(2, 3, tube, 4096, 128);
        for (size_t v = 0; v < m.positions.size(); ++v) {
            uint32_t h = uint32_t(v) * 2654435761u;
            h ^= h >> 15;
            h *= 2246822519u;
            h ^= h >> 13;
            const float noise = (float(h & 0xffffu) / 65535.0f - 0.5f) * 2.0f;  // [-1, 1]
            m.positions[v] += 0.002f * tube * noise * m.normals[v];
        }
        m.normals = geometry::angle_weighted_vertex_normals(m);
        return m;
    }();
    return mesh;
}

}  // namespace inkshade::bench
