#include "geometry/hard_edge_contours.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "analytic_meshes.hpp"
#include "geometry/auto_smooth.hpp"
#include "geometry/chaining.hpp"
#include "geometry/normals.hpp"

namespace inkshade::geometry {
namespace {

Mesh with_hard_edges(Mesh m) {
    ensure_vertex_normals(m);
    auto_smooth(m, 30.0f);
    return m;
}

Camera ortho(const glm::vec3& eye, const glm::vec3& up) {
    Camera c;
    c.eye = eye;
    c.up = up;
    c.orthographic = true;
    c.ortho_height = 5.0f;
    return c;
}

// A cube's contour is its outline: six whole edges, those between a face turned to the eye and
// one turned away, chained into one loop; nothing crosses a face.
TEST(HardEdgeContours, CubeOutlineRunsAlongItsEdges) {
    const Mesh cube = with_hard_edges(test::cube());
    for (bool perspective : {false, true}) {
        Camera camera = ortho({3.0f, 2.0f, 4.0f}, {0, 1, 0});
        camera.orthographic = !perspective;
        const std::vector<LineSegment> segments = extract_hard_edge_contours(cube, camera);
        std::set<std::pair<uint32_t, uint32_t>> drawn;
        for (const LineSegment& s : segments) {
            ASSERT_NE(s.edge_a, s.edge_b);
            // Both ends are cube corners (vertex keys), so each segment is a whole edge.
            ASSERT_EQ(s.edge_a >> 32, s.edge_a & 0xffffffffu);
            ASSERT_EQ(s.edge_b >> 32, s.edge_b & 0xffffffffu);
            const uint32_t a = uint32_t(s.edge_a), b = uint32_t(s.edge_b);
            EXPECT_EQ(s.a, cube.positions[a]);
            EXPECT_EQ(s.b, cube.positions[b]);
            drawn.insert({std::min(a, b), std::max(a, b)});
        }
        std::set<std::pair<uint32_t, uint32_t>> silhouette;
        for (const SilhouetteEdge& e : mesh_silhouette_edges(cube, camera)) silhouette.insert({e.v0, e.v1});
        EXPECT_EQ(drawn, silhouette);
        EXPECT_EQ(drawn.size(), 6u);
        const std::vector<Polyline> lines = chain_segments(segments);
        ASSERT_EQ(lines.size(), 1u);
        EXPECT_TRUE(lines[0].closed);
    }
}

// A capped cylinder (axis z, radius 1, height 2) seen from the side and above: its outline is
// the two generators where the side turns away, the far half of the top rim and the near half of
// the bottom rim — one closed loop, and nothing on the caps or across the side.
TEST(HardEdgeContours, CappedCylinderOutlineIsTwoGeneratorsAndTwoHalfRims) {
    constexpr float kPi = std::numbers::pi_v<float>;
    const Mesh m = with_hard_edges(test::capped_cylinder(1.0f, 64, 2.0f));
    const float elevation = 0.5f;  // radians above the side view
    const glm::vec3 toward_eye(0.0f, -std::cos(elevation), std::sin(elevation));
    const Camera camera = ortho(glm::vec3(0.0f, 0.0f, 1.0f) + 10.0f * toward_eye, {0, 0, 1});
    const std::vector<LineSegment> segments = extract_hard_edge_contours(m, camera);
    ASSERT_FALSE(segments.empty());
    float length = 0.0f;
    for (const LineSegment& s : segments) {
        length += glm::length(s.b - s.a);
        for (const glm::vec3& p : {s.a, s.b}) {
            const bool top = std::abs(p.z - 2.0f) < 1e-5f, bottom = std::abs(p.z) < 1e-5f;
            const float radius = std::hypot(p.x, p.y);
            if (top || bottom) {
                EXPECT_GT(radius, 0.99f) << "on a cap, inside its rim";
                // Top rim: the far half (y ≥ 0); bottom rim: the near half (y ≤ 0).
                EXPECT_LE(top ? -p.y : p.y, 1e-4f) << p.x << " " << p.y << " " << p.z;
            } else {
                // A generator: the side's normal (x, y, 0) is perpendicular to the view, y = 0.
                EXPECT_GT(std::abs(p.x), 0.99f);
                EXPECT_LT(std::abs(p.y), 0.05f);
            }
        }
    }
    // 2 generators of length 2 and two half rims of length π (polygon: a hair shorter).
    EXPECT_NEAR(length, 4.0f + 2.0f * kPi, 0.02f);
    const std::vector<Polyline> lines = chain_segments(segments);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_TRUE(lines[0].closed);
}

}  // namespace
}  // namespace inkshade::geometry
