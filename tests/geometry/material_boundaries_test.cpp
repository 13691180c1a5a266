// material-boundary on a unit cube built here, each side its own 4 vertices (as a model keeps a
// material's faces apart): the top (+y) and front (+z) sides are material 1, the rest 0, so the
// boundary is the 3 other edges of each of those two sides, and not the edge they share.
#include "geometry/material_boundaries.hpp"

#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "geometry/weld.hpp"

namespace inkshade::geometry {
namespace {

// Side k of the cube [0,1]³: the corners with coordinate `axis` = `value`, counter-clockwise
// seen from outside, as two triangles of their own 4 vertices.
void add_side(Mesh& m, int axis, float value, uint32_t material) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const uint32_t base = uint32_t(m.positions.size());
    for (auto [a, b] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
        glm::vec3 p(0.0f);
        p[axis] = value;
        p[u] = float(a);
        p[v] = float(b);
        m.positions.push_back(p);
    }
    const bool flip = value == 0.0f;
    m.triangles.emplace_back(base, flip ? base + 2 : base + 1, flip ? base + 1 : base + 2);
    m.triangles.emplace_back(base, flip ? base + 3 : base + 2, flip ? base + 2 : base + 3);
    m.face_materials.insert(m.face_materials.end(), 2, material);
}

Mesh two_material_cube() {
    Mesh m;
    for (int axis = 0; axis < 3; ++axis)
        for (float value : {0.0f, 1.0f}) add_side(m, axis, value, (axis == 1 || axis == 2) && value == 1.0f ? 1 : 0);
    m.materials.resize(2);
    return m;
}

using Edge = std::pair<std::tuple<float, float, float>, std::tuple<float, float, float>>;

Edge edge_of(glm::vec3 a, glm::vec3 b) {
    auto ta = std::tuple(a.x, a.y, a.z), tb = std::tuple(b.x, b.y, b.z);
    return ta < tb ? Edge{ta, tb} : Edge{tb, ta};
}

// The 3 edges of side (axis = 1) that do not lie on the plane `other` = 1, for both sides.
std::set<Edge> expected_boundary() {
    std::set<Edge> edges;
    const glm::vec3 corners[2][4] = {{{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}},   // top, y = 1
                                     {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};  // front, z = 1
    const int other[2] = {2, 1};  // the shared edge has z = 1 on the top, y = 1 on the front
    for (int s = 0; s < 2; ++s)
        for (int k = 0; k < 4; ++k) {
            const glm::vec3 a = corners[s][k], b = corners[s][(k + 1) % 4];
            if (!(a[other[s]] == 1.0f && b[other[s]] == 1.0f)) edges.insert(edge_of(a, b));
        }
    return edges;
}

void expect_boundary(const Mesh& cube) {
    const std::vector<LineSegment> segments = extract_material_boundaries(cube);
    std::set<Edge> found;
    for (const LineSegment& s : segments) found.insert(edge_of(s.a, s.b));
    EXPECT_EQ(segments.size(), 6u);
    EXPECT_EQ(found, expected_boundary());
}

TEST(MaterialBoundaries, TwoMaterialCubeHasExactlyTheBoundaryEdges) {
    expect_boundary(two_material_cube());  // sides apart: edges matched by position
}

TEST(MaterialBoundaries, WeldedCubeHasTheSameEdges) {
    Mesh cube = two_material_cube();
    weld(cube);
    ASSERT_EQ(cube.positions.size(), 8u);
    expect_boundary(cube);
}

TEST(MaterialBoundaries, NoneWithOneMaterialOrNoMaterials) {
    Mesh cube = two_material_cube();
    std::fill(cube.face_materials.begin(), cube.face_materials.end(), 1u);
    EXPECT_TRUE(extract_material_boundaries(cube).empty());
    cube.face_materials.clear();
    EXPECT_TRUE(extract_material_boundaries(cube).empty());
    cube.face_materials.assign(3, 0u);  // not one per face: ignored, no crash
    EXPECT_TRUE(extract_material_boundaries(cube).empty());
}

}  // namespace
}  // namespace inkshade::geometry
