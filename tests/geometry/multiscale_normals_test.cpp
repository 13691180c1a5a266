#include "geometry/multiscale_normals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/analytic_meshes.hpp"
#include "geometry/builtin_models.hpp"
#include "geometry/normals.hpp"

namespace inkshade::geometry {
namespace {

double angle_degrees(const glm::vec3& a, const glm::vec3& b) {
    return glm::degrees(std::acos(std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0)));
}

// On a sphere every neighbourhood is symmetric about its centre's radius: smoothing leaves the
// normals radial at every scale.
TEST(MultiscaleNormals, SphereNormalsStayRadial) {
    const Mesh sphere = builtin::sphere();
    const auto scales = multiscale_normals(sphere, sphere.normals, {0.02f, 0.05f, 0.1f, 0.2f, 0.4f});
    ASSERT_EQ(scales.size(), 5u);
    for (const auto& normals : scales) {
        ASSERT_EQ(normals.size(), sphere.positions.size());
        double worst = 0.0;
        for (size_t i = 0; i < normals.size(); ++i)
            worst = std::max(worst, angle_degrees(normals[i], sphere.positions[i]));
        EXPECT_LT(worst, 0.5);
    }
}

// A flat grid whose normals (data, not geometry) are n_L for x < 0 and n_R for x > 0: the
// Gaussian-weighted mean at distance x from the step is n_L Φ(−x/σ) + n_R Φ(x/σ), Φ the normal
// distribution's CDF.
TEST(MultiscaleNormals, StepOfNormalsIsBlurredByTheGaussian) {
    Mesh m;
    const int cells = 200;  // spacing 0.01 over [−1, 1]²
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            const float x = -1.0f + 2.0f * float(i) / cells, y = -1.0f + 2.0f * float(j) / cells;
            m.positions.push_back({x, y, 0.0f});
        }
    test::add_grid_triangles(m, cells, cells);
    const glm::dvec3 left = glm::normalize(glm::dvec3(-0.6, 0.0, 0.8)),
                     right = glm::normalize(glm::dvec3(0.6, 0.0, 0.8));
    for (const glm::vec3& p : m.positions) m.normals.push_back(glm::vec3(p.x < 0.0f ? left : right));
    const float sigma = 0.1f;
    const auto smoothed = smoothed_normals(m, m.normals, sigma);
    auto phi = [](double t) { return 0.5 * std::erfc(-t / std::sqrt(2.0)); };
    double worst = 0.0;
    int checked = 0;
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const glm::vec3 p = m.positions[i];
        if (std::abs(p.x) > 0.6f || std::abs(p.y) > 0.6f) continue;  // 3σ from the borders
        // The step lies halfway between the columns x = −0.01·k and 0: at x = 0 itself the
        // normal is n_R, so the step is at x = −0.005.
        const double x = double(p.x) + 0.005;
        const glm::dvec3 expected = glm::normalize(left * phi(-x / sigma) + right * phi(x / sigma));
        worst = std::max(worst, glm::length(glm::dvec3(smoothed[i]) - expected));
        ++checked;
    }
    EXPECT_GT(checked, 10000);
    EXPECT_LT(worst, 0.01);
}

// Detail at a fine scale is smoothed away at coarser scales: a sphere with radial bumps of
// wavelength about 0.1 has its vertex normals tilted by several degrees; smoothed at σ ≥ 0.05
// (a Gaussian keeps exp(−(2π/λ)² σ² / 2) ≈ 1 % of such a wave) they come back to within a
// tenth of that tilt of the exact sphere's.
TEST(MultiscaleNormals, NoisySphereCoarseNormalsApproachTheExactOnes) {
    Mesh m = builtin::sphere();
    for (glm::vec3& p : m.positions) {
        const glm::vec3 u = glm::normalize(p);
        p = u * (1.0f + 0.01f * std::sin(60.0f * u.x) * std::sin(60.0f * u.y) * std::sin(60.0f * u.z));
    }
    m.normals.clear();
    ensure_vertex_normals(m);
    auto mean_error = [&](const std::vector<glm::vec3>& normals) {
        double sum = 0.0;
        for (size_t i = 0; i < normals.size(); ++i) sum += angle_degrees(normals[i], m.positions[i]);
        return sum / double(normals.size());
    };
    const double fine = mean_error(m.normals);
    EXPECT_GT(fine, 3.0) << "the bumps tilt the normals";
    const auto scales = multiscale_normals(m, m.normals, {0.05f, 0.1f, 0.2f});
    for (const auto& normals : scales) EXPECT_LT(mean_error(normals), 0.1 * fine);
}

TEST(MultiscaleNormals, BadInputsAreKeptAndNothingCrashes) {
    Mesh m = builtin::sphere();
    EXPECT_EQ(smoothed_normals(m, m.normals, 0.0f), m.normals);
    EXPECT_EQ(smoothed_normals(m, m.normals, std::nanf("")), m.normals);
    EXPECT_TRUE(smoothed_normals(Mesh{}, {}, 0.1f).empty());
    m.positions[5] = glm::vec3(std::nanf(""));
    m.normals[7] = glm::vec3(std::nanf(""));
    m.triangles.push_back({0u, 1u, 999999u});
    const auto out = smoothed_normals(m, m.normals, 0.1f);
    ASSERT_EQ(out.size(), m.normals.size());
    for (size_t i = 0; i < out.size(); ++i) {
        if (i != 7) {
            EXPECT_TRUE(std::isfinite(out[i].x + out[i].y + out[i].z)) << i;
        }
    }
}

}  // namespace
}  // namespace inkshade::geometry
