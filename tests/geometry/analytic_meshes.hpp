// Meshes of analytic surfaces built by the geometry tests (the built-in models cover spheres
// and tori; these are shapes with known curvature that the product has no use for).
#pragma once
#include <cmath>
#include <numbers>

#include "geometry/weld.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::test {

// Two triangles for each cell of a grid of (nx + 1) x (ny + 1) vertices numbered row by row
// (vertex (i, j) is j (nx + 1) + i), counter-clockwise seen from where x × y points.
inline void add_grid_triangles(Mesh& m, int nx, int ny) {
    const auto idx = [&](int i, int j) { return uint32_t(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            m.triangles.emplace_back(idx(i, j), idx(i + 1, j), idx(i + 1, j + 1));
            m.triangles.emplace_back(idx(i, j), idx(i + 1, j + 1), idx(i, j + 1));
        }
}

// A fan of five unequal triangles around a raised centre (vertex 0): weighting by area and by
// angle give clearly different normals at the centre.
inline Mesh uneven_fan() {
    Mesh m;
    m.positions = {{0, 0, 0.6f}};
    const float degrees[] = {0, 40, 80, 200, 300}, radii[] = {1.0f, 0.5f, 1.5f, 1.0f, 0.8f};
    for (int i = 0; i < 5; ++i) {
        const float a = degrees[i] * std::numbers::pi_v<float> / 180.0f;
        m.positions.push_back(radii[i] * glm::vec3(std::cos(a), std::sin(a), 0.0f));
    }
    for (uint32_t i = 0; i < 5; ++i) m.triangles.push_back({0, 1 + i, 1 + (i + 1) % 5});
    return m;
}

// z = A cos(k x) over [−1.2, 1.2] × [−0.5, 0.5] moved by `shift` along x, k = 2π, A k = 1,
// analytic normals: crests (ridges, k1 = A k² = 2π) at integer x, troughs (valleys, k2 = −2π)
// at half-integers.
inline Mesh wave(float shift, int nx = 240, int ny = 50) {
    constexpr float kPi = std::numbers::pi_v<float>;
    const float k = 2.0f * kPi, A = 1.0f / k;
    Mesh m;
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const float x = -1.2f + shift + 2.4f * float(i) / float(nx);
            const float y = -0.5f + float(j) / float(ny);
            m.positions.emplace_back(x, y, A * std::cos(k * x));
            m.normals.push_back(glm::normalize(glm::vec3(A * k * std::sin(k * x), 0.0f, 1.0f)));
        }
    add_grid_triangles(m, nx, ny);
    return m;
}

// Open cylinder of radius r around the z axis: `around` segments, `rows` rings from z = 0 to
// `height`, counter-clockwise seen from outside, analytic normals.
inline Mesh cylinder(float r, int around, int rows, float height) {
    constexpr float kPi = std::numbers::pi_v<float>;
    Mesh m;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < around; ++i) {
            const float a = 2.0f * kPi * float(i) / float(around);
            const glm::vec3 n(std::cos(a), std::sin(a), 0.0f);
            m.positions.push_back(r * n + glm::vec3(0.0f, 0.0f, height * float(j) / float(rows - 1)));
            m.normals.push_back(n);
        }
    const auto idx = [&](int i, int j) { return uint32_t(j * around + i % around); };
    for (int j = 0; j + 1 < rows; ++j)
        for (int i = 0; i < around; ++i) {
            m.triangles.emplace_back(idx(i, j), idx(i + 1, j), idx(i + 1, j + 1));
            m.triangles.emplace_back(idx(i, j), idx(i + 1, j + 1), idx(i, j + 1));
        }
    return m;
}

// The cylinder above closed by two flat caps (a centre vertex and a fan each), without normals:
// what a CAD export of a round bar is. Faces counter-clockwise seen from outside.
inline Mesh capped_cylinder(float r, int around, float height) {
    Mesh m = cylinder(r, around, 2, height);
    m.normals.clear();
    const uint32_t bottom = uint32_t(m.positions.size()), top = bottom + 1;
    m.positions.push_back({0.0f, 0.0f, 0.0f});
    m.positions.push_back({0.0f, 0.0f, height});
    for (int i = 0; i < around; ++i) {
        const uint32_t i0 = uint32_t(i), i1 = uint32_t((i + 1) % around);
        m.triangles.emplace_back(bottom, i1, i0);
        m.triangles.emplace_back(top, uint32_t(around) + i0, uint32_t(around) + i1);
    }
    return m;
}

// The axis-aligned cube [-h, h]³: 8 vertices, 12 outward triangles, no normals.
inline Mesh cube(float h = 1.0f) {
    Mesh m;
    for (int i = 0; i < 8; ++i) m.positions.push_back(h * glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        m.triangles.emplace_back(q[0], q[1], q[2]);
        m.triangles.emplace_back(q[0], q[2], q[3]);
    }
    return m;
}

// The axis-aligned box [lo, hi]: the cube above stretched.
inline Mesh box(glm::vec3 lo, glm::vec3 hi) {
    Mesh m = cube(1.0f);
    for (glm::vec3& p : m.positions) p = lo + (p + 1.0f) * 0.5f * (hi - lo);
    return m;
}

// The cube [-1, 1]³ with each side an n x n grid of quads, welded: a CAD part whose flat sides
// meet at 90° along 12 n mesh edges.
inline Mesh meshed_cube(int n) {
    Mesh m;
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int a = 0; a < 3; ++a)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 u = axes[(a + 1) % 3], v = axes[(a + 2) % 3];  // u × v = axes[a]
            if (sign < 0.0f) std::swap(u, v);                        // u × v = the outward normal
            const uint32_t base = uint32_t(m.positions.size());
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i)
                    m.positions.push_back(sign * axes[a] + (2.0f * float(i) / float(n) - 1.0f) * u +
                                          (2.0f * float(j) / float(n) - 1.0f) * v);
            const size_t first = m.triangles.size();
            add_grid_triangles(m, n, n);
            for (size_t f = first; f < m.triangles.size(); ++f) m.triangles[f] += glm::uvec3(base);
        }
    geometry::weld(m);
    return m;
}

// A scan stand-in: a sphere of 6 n² quads (meshed_cube(n) pushed onto the unit sphere, so its
// faces are nearly even) with every vertex moved radially by up to ± amplitude × the mean edge
// length (a deterministic hash, like scanner noise), no normals. At amplitude 0.3 the noise
// alone tilts about a tenth of neighbouring faces more than 30° apart.
inline Mesh noisy_sphere(int n, float amplitude) {
    Mesh m = meshed_cube(n);
    const float edge = 0.5f * std::numbers::pi_v<float> / float(n);
    for (size_t v = 0; v < m.positions.size(); ++v) {
        uint32_t h = uint32_t(v) * 2654435761u;
        h ^= h >> 15;
        h *= 2246822519u;
        h ^= h >> 13;
        const float noise = float(h & 0xffffu) / 65535.0f * 2.0f - 1.0f;  // [-1, 1]
        m.positions[v] = glm::normalize(m.positions[v]) * (1.0f + amplitude * edge * noise);
    }
    m.normals.clear();
    return m;
}

}  // namespace inkshade::test
