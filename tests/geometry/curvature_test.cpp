#include "geometry/curvature.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>

#include "geometry/analytic_meshes.hpp"
#include "geometry/builtin_models.hpp"
#include "geometry/normals.hpp"

namespace inkshade::geometry {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::vec4& v) { return finite(glm::vec3(v)) && std::isfinite(v.w); }

using test::cylinder;

void expect_frame(const Curvature& c, const std::vector<glm::vec3>& normals, size_t v) {
    EXPECT_NEAR(glm::length(c.pdir1[v]), 1.0f, 1e-4f) << v;
    EXPECT_NEAR(glm::length(c.pdir2[v]), 1.0f, 1e-4f) << v;
    EXPECT_NEAR(glm::dot(c.pdir1[v], c.pdir2[v]), 0.0f, 1e-4f) << v;
    EXPECT_NEAR(glm::dot(c.pdir1[v], normals[v]), 0.0f, 1e-4f) << v;
    EXPECT_NEAR(glm::dot(glm::cross(c.pdir1[v], c.pdir2[v]), normals[v]), 1.0f, 1e-4f) << v;
}

class CurvatureSphere : public ::testing::TestWithParam<float> {};

TEST_P(CurvatureSphere, BothPrincipalCurvaturesAreInverseRadiusEverywhere) {
    const float r = GetParam();
    const Mesh m = builtin::sphere(64, 128, r);
    const Curvature c = compute_curvature(m, m.normals);
    ASSERT_EQ(c.k1.size(), m.vertex_count());
    for (size_t v = 0; v < m.vertex_count(); ++v) {  // poles included
        EXPECT_NEAR(c.k1[v], 1.0f / r, 0.01f / r) << v;
        EXPECT_NEAR(c.k2[v], 1.0f / r, 0.01f / r) << v;
        EXPECT_GE(c.k1[v], c.k2[v]);
        expect_frame(c, m.normals, v);
        // Constant curvature: no derivative (relative to the curvature scale 1/r²).
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(c.dcurv[v][k], 0.0f, 0.01f / (r * r)) << v;
    }
}

TEST_P(CurvatureSphere, AngleWeightedNormalsAlsoGiveInverseRadius) {
    const float r = GetParam();
    const Mesh m = builtin::sphere(64, 128, r);
    const auto normals = angle_weighted_vertex_normals(m);
    const Curvature c = compute_curvature(m, normals);
    for (size_t v = 0; v < m.vertex_count(); ++v) {
        if (std::abs(m.positions[v].y) > 0.95f * r) continue;  // thin fan triangles at the poles
        EXPECT_NEAR(c.k1[v], 1.0f / r, 0.01f / r) << v;
        EXPECT_NEAR(c.k2[v], 1.0f / r, 0.01f / r) << v;
    }
}

INSTANTIATE_TEST_SUITE_P(Curvature, CurvatureSphere, ::testing::Values(0.5f, 2.0f));

TEST(Curvature, CylinderBendsAroundAndIsStraightAlongTheAxis) {
    const float r = 1.5f;
    const int around = 256, rows = 40;
    const Mesh m = cylinder(r, around, rows, 2.0f * kPi * r / around * (rows - 1));
    const Curvature c = compute_curvature(m, m.normals);
    for (int j = 2; j + 2 < rows; ++j)
        for (int i = 0; i < around; ++i) {
            const size_t v = size_t(j * around + i);
            const float a = 2.0f * kPi * float(i) / float(around);
            EXPECT_NEAR(c.k1[v], 1.0f / r, 0.01f / r) << v;
            EXPECT_NEAR(c.k2[v], 0.0f, 0.01f / r) << v;
            EXPECT_GT(std::abs(glm::dot(c.pdir1[v], glm::vec3(-std::sin(a), std::cos(a), 0.0f))), 0.999f) << v;
            EXPECT_GT(std::abs(c.pdir2[v].z), 0.999f) << v;
            expect_frame(c, m.normals, v);
        }
}

// Torus S(u, v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v), outward normal
// (cos v cos u, cos v sin u, sin v). The principal directions are the tube circle (∂v, curvature
// 1/r) and the big circle (∂u, curvature cos v / (R + r cos v)). Since 1/r > 1/(R - r), the tube
// direction is always pdir1.
struct TorusPoint {
    float u, v;
    glm::vec3 along_tube, along_ring;  // unit ∂v, ∂u
};

TorusPoint torus_point(const glm::vec3& p, float major) {
    TorusPoint t;
    t.u = std::atan2(p.y, p.x);
    t.v = std::atan2(p.z, std::hypot(p.x, p.y) - major);
    t.along_tube = {-std::sin(t.v) * std::cos(t.u), -std::sin(t.v) * std::sin(t.u), std::cos(t.v)};
    t.along_ring = {-std::sin(t.u), std::cos(t.u), 0.0f};
    return t;
}

TEST(Curvature, TorusPrincipalCurvaturesAndDirections) {
    const float R = 1.0f, r = 0.4f;
    const Mesh m = builtin::torus(R, r, 256, 128);
    const Curvature c = compute_curvature(m, m.normals);
    for (size_t v = 0; v < m.vertex_count(); ++v) {
        const TorusPoint t = torus_point(m.positions[v], R);
        const float ring = std::cos(t.v) / (R + r * std::cos(t.v));
        EXPECT_NEAR(c.k1[v], 1.0f / r, 0.02f / r) << v;
        // 2% of the value, and of the ring curvature's scale 1/R where the value crosses zero.
        EXPECT_NEAR(c.k2[v], ring, 0.02f * std::max(std::abs(ring), 1.0f / R)) << v;
        EXPECT_GT(std::abs(glm::dot(c.pdir1[v], t.along_tube)), 0.999f) << v;
        EXPECT_GT(std::abs(glm::dot(c.pdir2[v], t.along_ring)), 0.999f) << v;
        expect_frame(c, m.normals, v);
    }
}

// Derivative tensor on the torus. k1 = 1/r is constant, and nothing changes along u, so
// C111 = ∂k1/∂s1 = 0, C112 = ∂k1/∂s2 = 0 and C222 = ∂k2/∂s2 = 0. The ring curvature varies along
// the tube (arc length s1 = r v): C122 = ∂k2/∂s1 = (1/r) d/dv [cos v / (R + r cos v)]
//   = −R sin v / (r (R + r cos v)²), with the sign of pdir1 · ∂v.
TEST(Curvature, TorusDerivativeTensorMatchesAnalytic) {
    const float R = 1.0f, r = 0.4f;
    const Mesh m = builtin::torus(R, r, 256, 128);
    const Curvature c = compute_curvature(m, m.normals);
    float scale = 0.0f;  // largest |C122| on the torus
    for (int k = 0; k < 3600; ++k) {
        const float v = 2.0f * kPi * float(k) / 3600.0f;
        scale = std::max(scale, std::abs(R * std::sin(v) / (r * (R + r * std::cos(v)) * (R + r * std::cos(v)))));
    }
    for (size_t v = 0; v < m.vertex_count(); ++v) {
        const TorusPoint t = torus_point(m.positions[v], R);
        const float sign = glm::dot(c.pdir1[v], t.along_tube) > 0.0f ? 1.0f : -1.0f;
        const float q = R + r * std::cos(t.v);
        const float c122 = -sign * R * std::sin(t.v) / (r * q * q);
        EXPECT_NEAR(c.dcurv[v].z, c122, 0.05f * std::abs(c122) + 0.01f * scale) << v << " v=" << t.v;
        EXPECT_NEAR(c.dcurv[v].x, 0.0f, 0.01f * scale) << v;
        EXPECT_NEAR(c.dcurv[v].y, 0.0f, 0.01f * scale) << v;
        EXPECT_NEAR(c.dcurv[v].w, 0.0f, 0.01f * scale) << v;
    }
}

TEST(Curvature, TorusPointAreasSumToSurfaceArea) {
    const float R = 1.0f, r = 0.4f;
    const Mesh m = builtin::torus(R, r, 256, 128);
    const Curvature c = compute_curvature(m, m.normals);
    double total = 0.0, mesh_area = 0.0;
    for (float a : c.point_area) total += a;
    for (const glm::uvec3& t : m.triangles)
        mesh_area +=
            0.5 * glm::length(glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]));
    EXPECT_NEAR(total, mesh_area, 1e-4 * mesh_area);
    EXPECT_NEAR(total, 4.0 * kPi * kPi * R * r, 2e-3 * total);
}

// Meyer et al. 2003: Voronoi areas inside a non-obtuse triangle, (A/4, A/4, A/2) for an obtuse one.
TEST(Curvature, PointAreasAreMixedVoronoiAreas) {
    Mesh m;
    m.positions = {{0, 0, 0}, {4, 0, 0}, {2, 0.5f, 0}, {10, 0, 0}, {13, 0, 0}, {11, 2, 0}};
    m.triangles = {{0, 1, 2}, {3, 4, 5}};
    const std::vector<glm::vec3> normals(6, glm::vec3(0, 0, 1));
    const Curvature c = compute_curvature(m, normals);
    EXPECT_NEAR(c.point_area[0], 0.25f, 1e-6f);  // obtuse at vertex 2, area 1
    EXPECT_NEAR(c.point_area[1], 0.25f, 1e-6f);
    EXPECT_NEAR(c.point_area[2], 0.5f, 1e-6f);
    // Acute triangle: A_i = (|e_ij|² cot γ_k + |e_ik|² cot γ_j) / 8.
    const glm::vec3 p[3] = {m.positions[3], m.positions[4], m.positions[5]};
    const auto cot = [&](int i) {
        const glm::vec3 a = p[(i + 1) % 3] - p[i], b = p[(i + 2) % 3] - p[i];
        return glm::dot(a, b) / glm::length(glm::cross(a, b));
    };
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        const float l2ij = glm::dot(p[j] - p[i], p[j] - p[i]), l2ik = glm::dot(p[k] - p[i], p[k] - p[i]);
        EXPECT_NEAR(c.point_area[3 + i], (l2ij * cot(k) + l2ik * cot(j)) / 8.0f, 1e-5f) << i;
    }
    EXPECT_EQ(c.k1[0], 0.0f);  // flat
}

TEST(Curvature, DegenerateInputGivesFiniteValues) {
    Mesh m;
    m.positions = {{0, 0, 0},     {1, 0, 0}, {0, 1, 0}, {1, 1, 0.2f},                 // two good faces
                   {0, -1, 0.3f}, {0, 0, 1},                                          // fins on edge 0-1
                   {2, 0, 0},                                                         // collinear with 0, 1
                   {5, 5, 5},                                                         // isolated
                   {0, 2, 0}};                                                        // zero normal given
    m.triangles = {{0, 1, 2}, {1, 3, 2}, {0, 1, 4}, {1, 0, 5}, {0, 1, 5}, {0, 0, 1},  // repeated index
                   {0, 1, 6},                                                         // zero area
                   {2, 3, 8},    // touches the vertex with a zero normal
                   {2, 3, 99}};  // index out of range
    std::vector<glm::vec3> normals = angle_weighted_vertex_normals(m);
    normals[8] = glm::vec3(0.0f);
    const Curvature c = compute_curvature(m, normals);
    ASSERT_EQ(c.k1.size(), m.vertex_count());
    for (size_t v = 0; v < m.vertex_count(); ++v) {
        EXPECT_TRUE(std::isfinite(c.k1[v]) && std::isfinite(c.k2[v])) << v;
        EXPECT_TRUE(finite(c.pdir1[v]) && finite(c.pdir2[v])) << v;
        EXPECT_TRUE(finite(c.dcurv[v])) << v;
        EXPECT_TRUE(std::isfinite(c.point_area[v])) << v;
        EXPECT_GE(c.k1[v], c.k2[v]) << v;
    }
    EXPECT_EQ(c.point_area[7], 0.0f);
    EXPECT_EQ(c.k1[7], 0.0f);
    EXPECT_EQ(c.point_area[8], 0.0f);
    EXPECT_GT(c.point_area[0], 0.0f);
    // Fewer normals than vertices: the rest count as unusable, not as out-of-bounds reads.
    const Curvature partial = compute_curvature(m, std::vector<glm::vec3>(normals.begin(), normals.begin() + 3));
    for (size_t v = 0; v < m.vertex_count(); ++v) EXPECT_TRUE(std::isfinite(partial.k1[v])) << v;
}

TEST(Curvature, ResultDoesNotDependOnThreadCount) {
    Mesh m = builtin::torus_knot(2, 3, 0.15f, 1024, 64);
    const auto normals = angle_weighted_vertex_normals(m);
    const Curvature many = compute_curvature(m, normals);
    Curvature one;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = compute_curvature(m, normals);
    }
    const auto same = [](const auto& a, const auto& b) {
        return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
    };
    EXPECT_TRUE(same(many.k1, one.k1));
    EXPECT_TRUE(same(many.k2, one.k2));
    EXPECT_TRUE(same(many.pdir1, one.pdir1));
    EXPECT_TRUE(same(many.dcurv, one.dcurv));
    EXPECT_TRUE(same(many.point_area, one.point_area));
}

}  // namespace
}  // namespace inkshade::geometry
