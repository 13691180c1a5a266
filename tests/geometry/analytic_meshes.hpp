// Meshes of analytic surfaces built by the geometry tests (the built-in models cover spheres
// and tori; these are shapes with known curvature that the product has no use for).
#pragma once
#include <cmath>
#include <numbers>

#include "inkshade/mesh.hpp"

namespace inkshade::test {

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

}  // namespace inkshade::test
