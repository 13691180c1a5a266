#include "geometry/builtin_models.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "geometry/normals.hpp"
#include "inkshade/error.hpp"
#include "inkshade/mesh_stats.hpp"

namespace inkshade::builtin {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void expect_closed(const Mesh& m, long euler) {
    const MeshStats s = mesh_stats(m);
    EXPECT_EQ(s.boundary_edges, 0u);
    EXPECT_EQ(s.non_manifold_edges, 0u);
    EXPECT_EQ(s.degenerate_faces, 0u);
    EXPECT_EQ(s.duplicate_faces, 0u);
    EXPECT_EQ(s.unreferenced_vertices, 0u);
    EXPECT_EQ(s.components, 1u);
    EXPECT_EQ(s.euler_characteristic, euler);
}

// Each undirected edge of a closed, consistently oriented mesh is used once in each direction.
void expect_consistent_orientation(const Mesh& m) {
    std::vector<uint64_t> directed;
    for (const glm::uvec3& t : m.triangles)
        for (int k = 0; k < 3; ++k) directed.push_back((uint64_t(t[k]) << 32) | t[(k + 1) % 3]);
    std::sort(directed.begin(), directed.end());
    EXPECT_EQ(std::adjacent_find(directed.begin(), directed.end()), directed.end());
}

// Largest angle (degrees) between the model's analytic normals and angle-weighted ones.
double worst_normal_angle(const Mesh& m) {
    const auto aw = geometry::angle_weighted_vertex_normals(m);
    double worst = 0.0;
    for (size_t v = 0; v < m.vertex_count(); ++v) {
        const double c = std::clamp(double(glm::dot(m.normals[v], aw[v])), -1.0, 1.0);
        worst = std::max(worst, std::acos(c) * 180.0 / std::numbers::pi);
    }
    return worst;
}

void expect_unit_normals(const Mesh& m) {
    ASSERT_EQ(m.normals.size(), m.vertex_count());
    for (const glm::vec3& n : m.normals) {
        ASSERT_TRUE(finite(n));
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    }
}

// Face normals agree with the analytic normals at their corners: triangles face outward.
void expect_faces_outward(const Mesh& m) {
    const auto fn = geometry::face_normals(m);
    for (size_t f = 0; f < m.triangle_count(); ++f) {
        const glm::vec3 avg = m.normals[m.triangles[f].x] + m.normals[m.triangles[f].y] + m.normals[m.triangles[f].z];
        EXPECT_GT(glm::dot(fn[f], avg), 0.0f) << "face " << f;
    }
}

TEST(BuiltinModels, SphereIsClosedGenusZero) {
    const Mesh m = sphere();
    expect_closed(m, 2);
    expect_consistent_orientation(m);
    EXPECT_EQ(m.vertex_count(), size_t(2 + 63 * 128));
    EXPECT_EQ(m.triangle_count(), size_t(2 * 128 * 63));
}

TEST(BuiltinModels, SphereVerticesLieOnTheSphereWithRadialNormals) {
    const Mesh m = sphere(16, 32, 2.5f);
    expect_unit_normals(m);
    for (size_t v = 0; v < m.vertex_count(); ++v) {
        EXPECT_NEAR(glm::length(m.positions[v]), 2.5f, 1e-5f);
        EXPECT_GT(glm::dot(m.normals[v], glm::normalize(m.positions[v])), 0.99999f);
    }
    expect_faces_outward(m);
    EXPECT_LT(worst_normal_angle(m), 2.0);
}

TEST(BuiltinModels, CoarsestSphereIsAnOctahedronLikeClosedMesh) {
    const Mesh m = sphere(2, 3);
    expect_closed(m, 2);
    EXPECT_EQ(m.vertex_count(), 5u);
}

TEST(BuiltinModels, TorusIsClosedGenusOne) {
    const Mesh m = torus();
    expect_closed(m, 0);
    expect_consistent_orientation(m);
    EXPECT_EQ(m.vertex_count(), size_t(128 * 64));
}

TEST(BuiltinModels, TorusVerticesSatisfyTheImplicitEquation) {
    const float R = 1.5f, r = 0.5f;
    const Mesh m = torus(R, r, 48, 24);
    expect_unit_normals(m);
    for (size_t v = 0; v < m.vertex_count(); ++v) {
        const glm::vec3 p = m.positions[v];
        const float d = std::hypot(p.x, p.y) - R;
        EXPECT_NEAR(d * d + p.z * p.z, r * r, 1e-5f);
        // Outward: along the position relative to the nearest point of the tube's centre circle.
        const glm::vec3 centre = R * glm::normalize(glm::vec3(p.x, p.y, 0.0f));
        EXPECT_GT(glm::dot(m.normals[v], glm::normalize(p - centre)), 0.99999f);
    }
    expect_faces_outward(m);
    EXPECT_LT(worst_normal_angle(m), 3.0);
}

TEST(BuiltinModels, TorusKnotIsClosedGenusOne) {
    const Mesh m = torus_knot();
    expect_closed(m, 0);
    expect_consistent_orientation(m);
    EXPECT_EQ(m.vertex_count(), size_t(512 * 32));
}

TEST(BuiltinModels, TorusKnotNormalsPointAwayFromTheCurve) {
    const int p = 3, q = 5, segments = 256, tube_segments = 16;
    const float radius = 0.1f;
    const Mesh m = torus_knot(p, q, radius, segments, tube_segments);
    expect_closed(m, 0);
    expect_unit_normals(m);
    for (int i = 0; i < segments; ++i) {
        const double t = 2.0 * std::numbers::pi * i / segments;
        const glm::vec3 c(float((1.0 + 0.4 * std::cos(q * t)) * std::cos(p * t)),
                          float((1.0 + 0.4 * std::cos(q * t)) * std::sin(p * t)), float(0.4 * std::sin(q * t)));
        for (int j = 0; j < tube_segments; ++j) {
            const size_t v = size_t(i) * tube_segments + j;
            const glm::vec3 offset = m.positions[v] - c;
            EXPECT_NEAR(glm::length(offset), radius, 1e-5f);
            EXPECT_GT(glm::dot(m.normals[v], offset / radius), 0.9999f);
        }
    }
    expect_faces_outward(m);
    EXPECT_LT(worst_normal_angle(m), 5.0);
}

TEST(BuiltinModels, TorusKnotRejectsALink) { EXPECT_THROW(torus_knot(2, 4), InputError); }

TEST(BuiltinModels, TeapotStandsOnYZero) {
    const Mesh m = teapot();
    const BoundingBox b = m.bounds();
    EXPECT_EQ(b.min.y, 0.0f);
    EXPECT_NEAR(b.max.y, 3.15f, 1e-5f);  // knob top, in the data's units
    EXPECT_NEAR(b.min.x, -3.0f, 1e-5f);  // handle
    EXPECT_GT(b.max.x, 3.4f);            // spout tip
    EXPECT_NEAR(b.min.z, -2.0f, 1e-5f);  // body (y-up: the data's y became -z)
    EXPECT_NEAR(b.max.z, 2.0f, 1e-5f);
}

// builtin:teapot:ground=N: N × N quads facing up in the plane y = 0 the teapot stands on, under
// its centre, wider than it.
TEST(BuiltinModels, TeapotOnTheGround) {
    const Mesh plain = teapot(8);
    const Mesh m = by_name("teapot:subdivisions=8,ground=10");
    ASSERT_EQ(m.positions.size(), plain.positions.size() + 121);
    ASSERT_EQ(m.triangles.size(), plain.triangles.size() + 200);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    const BoundingBox teapot_box = plain.bounds(), box = m.bounds();
    EXPECT_EQ(box.min.y, 0.0f);
    EXPECT_LT(box.min.x, teapot_box.min.x);
    EXPECT_GT(box.max.z, teapot_box.max.z);
    for (size_t f = plain.triangles.size(); f < m.triangles.size(); ++f) {
        const glm::uvec3 t = m.triangles[f];
        const glm::vec3 n = glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]);
        EXPECT_GT(n.y, 0.0f);  // counter-clockwise seen from above
        EXPECT_EQ(m.positions[t.x].y, 0.0f);
    }
    EXPECT_THROW(by_name("teapot:ground=-1"), InputError);
}

TEST(BuiltinModels, TeapotTessellationCounts) {
    // 32 patches of 2n² triangles, less the n zero-area triangles of each of the 8 cusp
    // patches (knob top, bottom centre).
    for (int n : {4, 16}) {
        const Mesh m = teapot(n);
        EXPECT_EQ(m.triangle_count(), size_t(64 * n * n - 8 * n)) << "n = " << n;
    }
}

TEST(BuiltinModels, TeapotTopologyAfterWelding) {
    const Mesh m = teapot(16);
    const MeshStats s = mesh_stats(m);
    EXPECT_EQ(s.vertices, 8257u);
    EXPECT_EQ(s.triangles, 16256u);
    EXPECT_EQ(s.boundary_edges, 256u);  // 16n: rim lip, lid edge, handle and spout ends
    EXPECT_EQ(s.non_manifold_edges, 0u);
    EXPECT_EQ(s.degenerate_faces, 0u);
    EXPECT_EQ(s.duplicate_faces, 0u);
    EXPECT_EQ(s.components, 3u);
    EXPECT_EQ(s.euler_characteristic, 1);
    EXPECT_TRUE(m.welded);
    expect_consistent_orientation(m);
}

TEST(BuiltinModels, TeapotNormalsAreUnitAndMostlyMatchTheMesh) {
    const Mesh m = teapot();
    expect_unit_normals(m);
    expect_faces_outward(m);
    const auto aw = geometry::angle_weighted_vertex_normals(m);
    size_t close = 0;
    for (size_t v = 0; v < m.vertex_count(); ++v)
        if (glm::dot(m.normals[v], aw[v]) > std::cos(5.0 * std::numbers::pi / 180.0)) ++close;
    // Only the creases of Newell's data differ: the body/bottom seam, the handle contact.
    EXPECT_GT(double(close) / double(m.vertex_count()), 0.98);
    EXPECT_LT(worst_normal_angle(m), 45.0);
}

TEST(BuiltinModels, TeapotBodyNormalsPointOutward) {
    const Mesh m = teapot();
    for (size_t v = 0; v < m.vertex_count(); ++v) {
        const glm::vec3 p = m.positions[v];
        const float r = std::hypot(p.x, p.z);
        // The body's side, away from spout and handle, faces away from the y axis.
        if (p.y > 0.3f && p.y < 2.3f && r > 1.6f && std::abs(p.z) > 0.7f) {
            EXPECT_GT(glm::dot(m.normals[v], glm::vec3(p.x, 0, p.z) / r), 0.5f);
        }
        if (p.y > 3.14f) {  // knob top
            EXPECT_GT(m.normals[v].y, 0.5f);
        }
        if (p.y < 1e-3f) {  // bottom
            EXPECT_LT(m.normals[v].y, -0.5f);
        }
    }
}

TEST(BuiltinModels, ByNameBuildsEveryListedModel) {
    for (const std::string& name : names()) {
        const Mesh m = by_name(name);
        EXPECT_GT(m.triangle_count(), 1000u) << name;
        EXPECT_TRUE(geometry::normals_are_sane(m)) << name;
    }
    EXPECT_EQ(names(), (std::vector<std::string>{"sphere", "torus", "torus-knot", "teapot"}));
}

TEST(BuiltinModels, UnknownNameThrowsInputError) {
    try {
        by_name("cube");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(),
                     "builtin:cube: unknown built-in model (choose sphere, torus, torus-knot, "
                     "teapot)");
    }
}

TEST(BuiltinModels, BadParametersThrowInputError) {
    EXPECT_THROW(sphere(1, 8), InputError);
    EXPECT_THROW(torus(1.0f, 1.5f), InputError);
    EXPECT_THROW(teapot(0), InputError);
}

}  // namespace
}  // namespace inkshade::builtin

namespace inkshade {
namespace {

TEST(BuiltinByName, OptionsChangeTessellation) {
    Mesh m = builtin::by_name("sphere:rings=10,segments=20");
    EXPECT_EQ(m.triangle_count(), 2u * 10u * 20u - 2u * 20u);  // pole rows are triangles, not quads
    Mesh t = builtin::by_name("torus:major-segments=12,minor-segments=8,minor=0.25");
    EXPECT_EQ(t.triangle_count(), 2u * 12u * 8u);
    EXPECT_NEAR(t.bounds().max.z, 0.25f, 1e-5f);
}

TEST(BuiltinByName, BadOptionsAreInputErrors) {
    for (const char* bad : {"sphere:rings", "sphere:rings=abc", "sphere:colour=3", "teapot:subdivisions=2.5",
                            "sphere:rings=100000,segments=100000", "torus:minor=nan", "cube"})
        EXPECT_THROW(builtin::by_name(bad), InputError) << bad;
}

}  // namespace
}  // namespace inkshade
