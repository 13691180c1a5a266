#include "geometry/auto_smooth.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "analytic_meshes.hpp"
#include "geometry/adjacency.hpp"
#include "geometry/hard_edge_contours.hpp"
#include "geometry/normals.hpp"

namespace inkshade::geometry {
namespace {

glm::vec3 shading_normal(const Mesh& m, size_t f, int k) { return m.shading_normal(f, k); }

TEST(AutoSmooth, CubeCornersTakeTheirFaceNormal) {
    Mesh cube = test::cube();
    ensure_vertex_normals(cube);
    const std::vector<glm::vec3> smooth = cube.normals;
    auto_smooth(cube, 30.0f);
    ASSERT_TRUE(cube.has_hard_edges());
    EXPECT_EQ(cube.shading_normal_count(), 24u);  // three faces (fans) at each of 8 corners
    const std::vector<glm::vec3> fn = face_normals(cube);
    for (size_t f = 0; f < cube.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) EXPECT_LT(glm::length(shading_normal(cube, f, k) - fn[f]), 1e-6f) << f << " " << k;
    EXPECT_EQ(cube.normals, smooth);  // the smooth field is left for curvature and the hull
}

TEST(AutoSmooth, AngleOf180OrNoHardEdgeLeavesNothing) {
    Mesh cube = test::cube();
    ensure_vertex_normals(cube);
    auto_smooth(cube, 180.0f);
    EXPECT_FALSE(cube.has_hard_edges());
    EXPECT_TRUE(cube.shading_splits.empty());
    auto_smooth(cube, 91.0f);  // the cube's edges are 90°: all smooth
    EXPECT_FALSE(cube.has_hard_edges());
    auto_smooth(cube, 89.0f);
    EXPECT_TRUE(cube.has_hard_edges());
}

TEST(AutoSmooth, CylinderSideStaysSmoothAndCapsFlat) {
    // 32 segments: 11.25° between side faces (smooth at 30°), 90° to the caps (hard).
    Mesh m = test::capped_cylinder(1.0f, 32, 2.0f);
    ensure_vertex_normals(m);
    auto_smooth(m, 30.0f);
    ASSERT_TRUE(m.has_hard_edges());
    const std::vector<glm::vec3> fn = face_normals(m);
    for (size_t f = 0; f < m.triangles.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 p = m.positions[m.triangles[f][k]], n = shading_normal(m, f, k);
            if (std::abs(fn[f].z) > 0.99f) {
                EXPECT_LT(glm::length(n - fn[f]), 1e-6f);  // cap: flat
            } else {
                // Side: the radial direction (the mean of the two faces at the vertex).
                EXPECT_LT(glm::length(n - glm::normalize(glm::vec3(p.x, p.y, 0.0f))), 1e-5f);
            }
        }
    }
    // Rim vertices have two fans (side, cap), cap centres and nothing else one.
    EXPECT_EQ(m.shading_normal_count(), 2u * 64u + 2u);
}

// Area weighting (three.js's convention) inside a fan: an uneven fan of five faces around a
// raised centre, plus a flap on the edge (0, 1) that makes it hard; the five faces stay one fan
// (joined the other way round), whose normal is their sum of cross products, normalised.
TEST(AutoSmooth, AreaWeightedFansSumTheirFacesCrossProducts) {
    Mesh m = test::uneven_fan();
    glm::vec3 sum(0.0f), angle_sum(0.0f);
    for (const glm::uvec3& t : m.triangles) {
        const glm::vec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
        sum += glm::cross(b - a, c - a);
        angle_sum += angle_between(b - a, c - a) * glm::normalize(glm::cross(b - a, c - a));
    }
    m.positions.push_back({0.5f, 0.0f, -2.0f});
    m.triangles.push_back({0, 6, 1});  // the flap
    for (NormalWeighting w : {NormalWeighting::Area, NormalWeighting::Angle}) {
        Mesh s = m;
        ensure_vertex_normals(s, w);
        auto_smooth(s, 179.0f, w);  // only the three-face edge is hard
        ASSERT_TRUE(s.has_hard_edges());
        const glm::vec3 want = glm::normalize(w == NormalWeighting::Area ? sum : angle_sum);
        for (size_t f = 0; f < 5; ++f) EXPECT_LT(glm::length(shading_normal(s, f, 0) - want), 1e-5f) << f;
    }
    EXPECT_GT(glm::length(glm::normalize(sum) - glm::normalize(angle_sum)), 0.03f);
}

TEST(AutoSmooth, NonManifoldEdgesAreHardAndDegenerateFacesTakeTheSmoothNormal) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0.5f, 0, 0}};
    // Three nearly coplanar faces on the edge (0, 1), and a zero-area face (0, 5, 1).
    m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {0, 5, 1}, {0, 2, 2}};
    ensure_vertex_normals(m);
    auto_smooth(m, 179.0f);
    ASSERT_TRUE(m.has_hard_edges());
    std::set<uint32_t> at_vertex0;
    for (size_t f = 0; f < 3; ++f)
        for (int k = 0; k < 3; ++k)
            if (m.triangles[f][k] == 0) at_vertex0.insert(m.shading_normal_id(f, k));
    EXPECT_EQ(at_vertex0.size(), 3u);  // no face joins another across the three-face edge
    for (size_t f = 3; f < 5; ++f)
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = m.triangles[f][k];
            EXPECT_EQ(shading_normal(m, f, k), m.normals[v]) << f;
        }
}

// A CAD part keeps every crease: the denoising test averages each side of an edge on its own
// side only, and flat sides stay flat.
TEST(AutoSmooth, MeshedCubeKeepsAllTwelveEdgesHard) {
    Mesh cube = test::meshed_cube(8);
    ensure_vertex_normals(cube);
    auto_smooth(cube, 30.0f);
    ASSERT_TRUE(cube.has_hard_edges());
    EXPECT_EQ(hard_edge_table(cube).edges.size(), 12u * 8u);
    const std::vector<glm::vec3> fn = face_normals(cube);
    for (size_t f = 0; f < cube.triangles.size(); ++f)
        for (int k = 0; k < 3; ++k) EXPECT_LT(glm::length(shading_normal(cube, f, k) - fn[f]), 1e-6f) << f << " " << k;
}

// The split is stored where a hard edge ends, not per corner: on a meshed cube the shading
// splits grow with its 12 n crease edges (4x from n = 32 to 128, where the faces grow 16x) and
// at n = 128 take less than a byte per triangle (per-corner ids alone took twelve). Every
// corner off the creases shades with its smooth normal, and the ids number the fans without a
// gap.
TEST(AutoSmooth, SplitsGrowWithTheHardEdgesNotTheMesh) {
    size_t stored[2] = {0, 0};
    const int sizes[2] = {32, 128};
    for (int i = 0; i < 2; ++i) {
        Mesh cube = test::meshed_cube(sizes[i]);
        ensure_vertex_normals(cube);
        auto_smooth(cube, 30.0f);
        ASSERT_TRUE(cube.has_hard_edges());
        const ShadingSplits& s = cube.shading_splits;
        stored[i] = s.corner_face.size() + s.normals.size();
        if (i == 1) {
            EXPECT_LT(s.memory_bytes(), cube.triangle_count());
        }
        size_t split = 0;
        for (uint32_t v = 0; v < cube.vertex_count(); ++v) split += s.slot(v) != ShadingSplits::kNone;
        EXPECT_EQ(split, 12u * size_t(sizes[i] - 1) + 8u);  // the crease vertices, corners included
        std::set<uint32_t> ids;                             // every id below the count is some corner's
        for (size_t f = 0; f < cube.triangle_count(); ++f)
            for (int k = 0; k < 3; ++k) {
                ids.insert(cube.shading_normal_id(f, k));
                const uint32_t v = cube.triangles[f][k];
                if (s.slot(v) == ShadingSplits::kNone) {
                    EXPECT_EQ(cube.shading_normal(f, k), cube.normals[v]);
                }
            }
        EXPECT_EQ(ids.size(), cube.shading_normal_count());
        EXPECT_LT(*ids.rbegin(), cube.shading_normal_count());
    }
    EXPECT_LT(stored[1], 5 * stored[0]);
    EXPECT_GT(stored[1], 3 * stored[0]);
}

// A dense scan whose noise alone tilts neighbouring faces past 30° at one edge in twelve:
// averaged over the faces around them, nearly all of those edges are smooth (the renderer then
// takes the smooth path, rtsc's vertex normals, at no extra cost); the few left are where
// several vertices in a row stand out the same way.
TEST(AutoSmooth, NoisyScanKeepsFewHardEdges) {
    Mesh scan = test::noisy_sphere(64, 0.2f);
    ensure_vertex_normals(scan);
    const std::vector<glm::vec3> fn = face_normals(scan);
    const EdgeAdjacency adj = build_edge_adjacency(scan);
    size_t sharp = 0;
    for (size_t e = 0; e < adj.edge_count(); ++e)
        sharp +=
            adj.face_count(e) == 2 && glm::dot(fn[adj.face(e, 0)], fn[adj.face(e, 1)]) < std::cos(glm::radians(30.0f));
    EXPECT_GT(sharp, adj.edge_count() / 20);  // the noise often tilts neighbours more than 30° apart
    auto_smooth(scan, 30.0f);
    const size_t hard = scan.has_hard_edges() ? hard_edge_table(scan).edges.size() : 0;
    EXPECT_LT(hard, sharp / 50);  // at most 2 % of them stay hard
    auto_smooth(scan, 5.0f);      // a small angle still finds what stands out of the noise
    EXPECT_TRUE(scan.has_hard_edges());
}

TEST(AutoSmooth, IsDeterministic) {
    Mesh a = test::capped_cylinder(1.0f, 200, 1.0f), b = a;
    ensure_vertex_normals(a);
    ensure_vertex_normals(b);
    auto_smooth(a, 30.0f);
    auto_smooth(b, 30.0f);
    EXPECT_EQ(a.shading_splits, b.shading_splits);
}

}  // namespace
}  // namespace inkshade::geometry
