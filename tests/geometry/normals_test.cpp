#include "geometry/normals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "analytic_meshes.hpp"

namespace inkshade::geometry {
namespace {

// Indexed unit cube, counter-clockwise seen from outside.
Mesh cube() {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    m.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                   {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    return m;
}

void expect_near(const glm::vec3& a, const glm::vec3& b, float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Normals, FaceNormalFollowsCounterClockwiseWinding) {
    Mesh m;
    m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}};
    m.triangles = {{0, 1, 2}, {0, 2, 1}};
    const auto fn = face_normals(m);
    ASSERT_EQ(fn.size(), 2u);
    expect_near(fn[0], {0, 0, 1});
    expect_near(fn[1], {0, 0, -1});
}

TEST(Normals, CubeFaceNormalsPointOutward) {
    const Mesh m = cube();
    const auto fn = face_normals(m);
    const glm::vec3 centre(0.5f);
    for (size_t f = 0; f < m.triangle_count(); ++f) {
        const glm::uvec3 t = m.triangles[f];
        const glm::vec3 mid = (m.positions[t.x] + m.positions[t.y] + m.positions[t.z]) / 3.0f;
        EXPECT_GT(glm::dot(fn[f], mid - centre), 0.0f) << "face " << f;
        EXPECT_NEAR(glm::length(fn[f]), 1.0f, 1e-6f);
    }
}

TEST(Normals, CubeCornerAngleWeightedNormalIsDiagonal) {
    const Mesh m = cube();
    const auto vn = angle_weighted_vertex_normals(m);
    ASSERT_EQ(vn.size(), 8u);
    // Each of the three faces meets the corner at a right angle, however it is triangulated.
    expect_near(vn[6], glm::normalize(glm::vec3(1, 1, 1)));
    expect_near(vn[0], glm::normalize(glm::vec3(-1, -1, -1)));
    for (size_t v = 0; v < 8; ++v) expect_near(vn[v], glm::normalize(m.positions[v] - glm::vec3(0.5f)));
}

using test::uneven_fan;

// three.js r187 BufferGeometry.computeVertexNormals on an indexed geometry: per face
// cb = (C - B) x (A - B) added to its three vertices, then each normalised.
std::vector<glm::vec3> threejs_vertex_normals(const Mesh& m) {
    std::vector<glm::vec3> sum(m.positions.size(), glm::vec3(0.0f));
    for (const glm::uvec3& t : m.triangles) {
        const glm::vec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
        const glm::vec3 cb = glm::cross(c - b, a - b);
        for (int k = 0; k < 3; ++k) sum[t[k]] += cb;
    }
    for (glm::vec3& n : sum) n = glm::normalize(n);
    return sum;
}

TEST(Normals, AreaWeightingIsThreejsComputeVertexNormals) {
    const Mesh m = uneven_fan();
    const std::vector<glm::vec3> three = threejs_vertex_normals(m), area = area_weighted_vertex_normals(m);
    ASSERT_EQ(area.size(), three.size());
    for (size_t v = 0; v < area.size(); ++v) expect_near(area[v], three[v]);
    const glm::vec3 angle = angle_weighted_vertex_normals(m)[0];
    EXPECT_GT(glm::length(angle - area[0]), 0.03f) << "the fan does not tell the weightings apart";
    Mesh ensured = m;
    ensure_vertex_normals(ensured, NormalWeighting::Area);
    expect_near(ensured.normals[0], three[0]);
    ensured.normals.clear();
    ensure_vertex_normals(ensured);
    expect_near(ensured.normals[0], angle);
}

TEST(Normals, DegenerateFaceGivesZeroNormalWithoutNaN) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}, {0, 0, 3}, {0, 1, 3}};
    const auto fn = face_normals(m);
    EXPECT_EQ(fn[0], glm::vec3(0.0f));
    EXPECT_EQ(fn[1], glm::vec3(0.0f));
    const auto vn = angle_weighted_vertex_normals(m);
    for (const glm::vec3& n : vn) {
        EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    }
    expect_near(vn[1], {0, 0, 1});
}

TEST(Normals, IsolatedVertexGetsDefaultNormal) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
    m.triangles = {{0, 2, 1}};
    const auto vn = angle_weighted_vertex_normals(m);
    expect_near(vn[0], {0, 0, -1});
    expect_near(vn[3], {0, 0, 1});
}

TEST(Normals, SaneFileNormalsAreKeptAndRenormalised) {
    Mesh m = cube();
    m.normals.assign(8, glm::vec3(0, 2, 0));
    ASSERT_TRUE(normals_are_sane(m));
    ensure_vertex_normals(m);
    for (const glm::vec3& n : m.normals) expect_near(n, {0, 1, 0});
}

TEST(Normals, InsaneNormalsAreReplaced) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (const glm::vec3 bad : {glm::vec3(0.0f), glm::vec3(nan, 0, 0), glm::vec3(0, inf, 0)}) {
        Mesh m = cube();
        m.normals.assign(8, glm::vec3(0, 1, 0));
        m.normals[3] = bad;
        EXPECT_FALSE(normals_are_sane(m));
        ensure_vertex_normals(m);
        expect_near(m.normals[6], glm::normalize(glm::vec3(1, 1, 1)));
    }
}

TEST(Normals, WrongCountIsInsane) {
    Mesh m = cube();
    m.normals.assign(7, glm::vec3(0, 1, 0));
    EXPECT_FALSE(normals_are_sane(m));
    ensure_vertex_normals(m);
    EXPECT_EQ(m.normals.size(), 8u);
    m.normals.clear();
    EXPECT_FALSE(normals_are_sane(m));
}

TEST(Normals, LargeMeshIsDeterministic) {
    // Enough faces to split across TBB tasks; two runs must agree bit for bit.
    Mesh m;
    const int n = 300;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.positions.emplace_back(i, j, std::sin(0.1f * i) * std::cos(0.07f * j));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
            m.triangles.emplace_back(a, b, c);
            m.triangles.emplace_back(a, c, d);
        }
    const auto first = angle_weighted_vertex_normals(m);
    const auto second = angle_weighted_vertex_normals(m);
    EXPECT_EQ(first, second);
    for (const glm::vec3& v : first) EXPECT_GT(v.z, 0.0f);
}

}  // namespace
}  // namespace inkshade::geometry
