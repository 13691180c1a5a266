// typical_edge_length: the side of the equilateral triangle of the median triangle area, so a
// regular mesh gives its edge length, slivers count by area and a few huge triangles do not
// move it.
#include <gtest/gtest.h>

#include <cmath>

#include "render/edge_length.hpp"

namespace inkshade::test {
namespace {

// `n` equilateral triangles of side `side`, side by side along x.
Mesh equilateral_strip(int n, float side, float x0 = 0.0f) {
    Mesh m;
    const float h = side * std::sqrt(3.0f) / 2.0f;
    for (int i = 0; i < n; ++i) {
        const uint32_t b = uint32_t(m.positions.size());
        const float x = x0 + float(i) * side;
        m.positions.insert(m.positions.end(), {{x, 0, 0}, {x + side, 0, 0}, {x + 0.5f * side, h, 0}});
        m.triangles.push_back({b, b + 1, b + 2});
    }
    return m;
}

TEST(EdgeLength, EquilateralTrianglesGiveTheirSide) {
    EXPECT_NEAR(render::typical_edge_length(equilateral_strip(10, 0.25f)), 0.25f, 1e-5f);
}

TEST(EdgeLength, SliversCountByAreaAndTheMedianIgnoresAFewHugeTriangles) {
    Mesh m = equilateral_strip(9, 0.1f);
    const Mesh huge = equilateral_strip(4, 50.0f, 10.0f);
    for (const glm::uvec3& t : huge.triangles) m.triangles.push_back(t + uint32_t(m.positions.size()));
    m.positions.insert(m.positions.end(), huge.positions.begin(), huge.positions.end());
    EXPECT_NEAR(render::typical_edge_length(m), 0.1f, 1e-5f);
    // A right triangle with legs 0.01 and 4 (area 0.02): the equilateral side of that area.
    Mesh sliver;
    sliver.positions = {{0, 0, 0}, {0.01f, 0, 0}, {0, 4, 0}};
    sliver.triangles = {{0, 1, 2}};
    EXPECT_NEAR(render::typical_edge_length(sliver), std::sqrt(4.0f * 0.02f / std::sqrt(3.0f)), 1e-5f);
    EXPECT_EQ(render::typical_edge_length(Mesh{}), 0.0f);
}

}  // namespace
}  // namespace inkshade::test
