#include "geometry/ridges.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"
#include "geometry/analytic_meshes.hpp"
#include "geometry/normals.hpp"

namespace inkshade::geometry {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// The wave (analytic_meshes.hpp): crests (ridges, k1 = 2π) at integer x, troughs (valleys,
// k2 = −2π) at half-integers; the threshold at the default feature size (1 % of the 2.6
// diagonal) is 0.1 / 0.026 ≈ 3.8.
using test::wave;

// Checks that every segment inside the margin lies within `tol` of x = n/2 for n of the given
// parity, and returns the length drawn per such line.
std::map<int, double> lengths_near(const std::vector<LineSegment>& segs, int parity, float tol) {
    std::map<int, double> length;
    for (const LineSegment& s : segs) {
        const glm::vec3 mid = 0.5f * (s.a + s.b);
        if (std::abs(mid.x) > 1.1f || std::abs(mid.y) > 0.4f) continue;
        const int n = int(std::lround(2.0f * mid.x));
        EXPECT_EQ(((n % 2) + 2) % 2, parity) << "line near x = " << mid.x;
        for (const glm::vec3& p : {s.a, s.b}) EXPECT_NEAR(p.x, 0.5f * float(n), tol);
        length[n] += glm::distance(s.a, s.b);
    }
    return length;
}

TEST(Ridges, WaveRidgesOnCrestsAndValleysInTroughs) {
    // Grid shifted by a quarter step so that crests and troughs run between vertex columns
    // (through vertices, the sign of ∂k/∂s at a vertex is noise and the line frays).
    const Mesh m = wave(0.0025f);
    const RidgeLines lines = extract_ridges(m, compute_curvature(m, m.normals));
    ASSERT_FALSE(lines.ridges.empty());
    ASSERT_FALSE(lines.valleys.empty());
    const auto ridges = lengths_near(lines.ridges, 0, 0.005f);  // half a grid step
    const auto valleys = lengths_near(lines.valleys, 1, 0.005f);
    for (const int n : {-2, 0, 2}) EXPECT_GT(ridges.count(n) ? ridges.at(n) : 0.0, 0.78) << n;
    for (const int n : {-1, 1}) EXPECT_GT(valleys.count(n) ? valleys.at(n) : 0.0, 0.78) << n;
    // Each crest chains into one long polyline (edge keys shared exactly).
    int long_ridges = 0;
    for (const Polyline& l : chain_segments(lines.ridges)) long_ridges += polyline_length(l) > 0.8f;
    EXPECT_EQ(long_ridges, 3);
    // A threshold above the crest curvature (2π > 0.1 / feature size · 2) removes everything.
    EXPECT_TRUE(extract_ridges(m, compute_curvature(m, m.normals), {.threshold = 0.5f}).ridges.empty());
}

TEST(Ridges, NoneOnSphere) {
    const Mesh m = builtin::sphere(64, 128, 1.0f);
    const RidgeLines lines = extract_ridges(m, compute_curvature(m, m.normals));
    EXPECT_TRUE(lines.ridges.empty());
    EXPECT_TRUE(lines.valleys.empty());
}

TEST(Ridges, BadMeshesGiveResultsWithoutCrashing) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0.3f}, {0.5f, -1, 0.2f}, {0.5f, 0, 1},
                   {2, 2, 2}, {0, 0, 0}, {NAN, 0, 0},     {9, 9, 9}};
    m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {1, 1, 2}, {0, 1, 99}, {2, 4, 6}, {0, 6, 2}, {3, 4, 7}};
    m.normals = angle_weighted_vertex_normals(m);
    const Curvature c = compute_curvature(m, m.normals);
    const RidgeLines lines = extract_ridges(m, c, {.threshold = 0.0f});
    for (const auto* list : {&lines.ridges, &lines.valleys})
        for (const LineSegment& s : *list) EXPECT_NE(s.edge_a, s.edge_b);
    EXPECT_THROW(extract_ridges(m, Curvature{}), std::invalid_argument);
    EXPECT_TRUE(extract_ridges(Mesh{}, Curvature{}).ridges.empty());
}

}  // namespace
}  // namespace inkshade::geometry
