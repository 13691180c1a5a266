// The SVG's fills (geometry/visible_fills.hpp): the visible part of each material's faces,
// checked by area and shape against views whose answer is known: a sphere's disc, a square
// in front of a plate (the plate keeps a square hole), a triangle hidden behind another, and
// a sphere opened by a section plane (its inside shows, back faces and all).
#include "geometry/visible_fills.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/builtin_models.hpp"

namespace inkshade::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

double ring_area(const std::vector<glm::vec2>& ring) {
    double a = 0.0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const glm::dvec2 p(ring[i]), q(ring[(i + 1) % ring.size()]);
        a += p.x * q.y - p.y * q.x;
    }
    return 0.5 * a;
}

// Even-odd area: the rings of one region do not overlap, so outlines minus holes.
double region_area(const FillRegion& r) {
    double outer = 0.0, holes = 0.0, largest = 0.0;
    for (const auto& ring : r.rings) largest = std::max(largest, std::abs(ring_area(ring)));
    for (const auto& ring : r.rings)
        (std::abs(ring_area(ring)) == largest ? outer : holes) += std::abs(ring_area(ring));
    return outer - holes;
}

Camera ortho_camera(float height) {
    Camera c;
    c.eye = {0.0f, 0.0f, 10.0f};
    c.orthographic = true;
    c.ortho_height = height;
    c.near_plane = 1.0f;
    c.far_plane = 20.0f;
    return c;
}

void add_quad(Mesh& m, glm::vec3 centre, float half, uint32_t material) {
    const auto base = uint32_t(m.positions.size());
    for (glm::vec2 d : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
        m.positions.push_back(centre + half * glm::vec3(d, 0.0f));
    m.triangles.emplace_back(base, base + 1, base + 2);
    m.triangles.emplace_back(base, base + 2, base + 3);
    m.face_materials.insert(m.face_materials.end(), 2, material);
}

// Perspective view of the unit sphere from 5 units: its image is the disc of angular radius
// asin(1/5), tan of it times the focal length in pixels; the mesh's polygon is inscribed.
TEST(VisibleFills, SphereIsOneDisc) {
    const Mesh sphere = builtin::sphere(64, 128, 1.0f);
    Camera c;
    c.eye = {0.0f, 0.0f, 5.0f};
    c.fov_degrees = 30.0f;
    const int size = 400;
    const auto fills = visible_fills(sphere, c, size, size, std::nullopt, glm::vec3(0.2f, 0.4f, 0.6f));
    ASSERT_EQ(fills.size(), 1u);
    EXPECT_EQ(fills[0].color, glm::vec3(0.2f, 0.4f, 0.6f));
    ASSERT_EQ(fills[0].rings.size(), 1u) << "one outline, no holes";
    const double focal = 0.5 * size / std::tan(0.5 * 30.0 * kPi / 180.0);
    const double radius = focal * std::tan(std::asin(1.0 / 5.0));
    const double area = region_area(fills[0]);
    EXPECT_NEAR(area / (kPi * radius * radius), 1.0, 0.01);
    EXPECT_LT(area, kPi * radius * radius) << "the inscribed polygon is inside the disc";
    for (const glm::vec2& p : fills[0].rings[0])
        EXPECT_NEAR(glm::length(glm::dvec2(p) - glm::dvec2(200.0)), radius, 0.01 * radius);
}

// A square of material 1 in front of a larger plate of material 0, orthographic at 10 px a
// unit: the plate's region is its square minus the front one, exactly.
TEST(VisibleFills, FrontSquareCutsAHoleInThePlate) {
    Mesh m;
    add_quad(m, {0.0f, 0.0f, 0.0f}, 4.0f, 0);   // 80 x 80 px
    add_quad(m, {0.5f, -0.5f, 1.0f}, 1.0f, 1);  // 20 x 20 px, in front
    m.materials = {Material{.name = "plate", .diffuse = {1.0f, 0.0f, 0.0f}},
                   Material{.name = "front", .diffuse = {0.0f, 0.0f, 1.0f}}};
    const auto fills = visible_fills(m, ortho_camera(10.0f), 100, 100, std::nullopt, glm::vec3(1.0f));
    ASSERT_EQ(fills.size(), 2u);
    EXPECT_EQ(fills[0].material, 0u);
    EXPECT_EQ(fills[0].color, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(fills[0].rings.size(), 2u) << "outline and hole";
    EXPECT_NEAR(region_area(fills[0]), 80.0 * 80.0 - 20.0 * 20.0, 1e-2);
    EXPECT_NEAR(region_area(fills[1]), 20.0 * 20.0, 1e-2);
    // The front square's corners: centre (55, 55) px (image y down), half width 10 px.
    for (const glm::vec2& p : fills[1].rings[0]) {
        EXPECT_TRUE(std::abs(p.x - 45.0f) < 1e-3f || std::abs(p.x - 65.0f) < 1e-3f) << p.x;
        EXPECT_TRUE(std::abs(p.y - 45.0f) < 1e-3f || std::abs(p.y - 65.0f) < 1e-3f) << p.y;
    }
    // Behind instead: the plate covers it whole, so material 1 has no region.
    for (size_t i = 4; i < 8; ++i) m.positions[i].z = -1.0f;
    const auto hidden = visible_fills(m, ortho_camera(10.0f), 100, 100, std::nullopt, glm::vec3(1.0f));
    ASSERT_EQ(hidden.size(), 1u);
    EXPECT_EQ(hidden[0].rings.size(), 1u);
    EXPECT_NEAR(region_area(hidden[0]), 80.0 * 80.0, 1e-2);
}

// Regions are cut to the image: a plate larger than the view fills the whole image.
TEST(VisibleFills, RegionsStayInTheImage) {
    Mesh m;
    add_quad(m, {0.0f, 0.0f, 0.0f}, 50.0f, 0);
    const auto fills = visible_fills(m, ortho_camera(10.0f), 120, 100, std::nullopt, glm::vec3(1.0f));
    ASSERT_EQ(fills.size(), 1u);
    EXPECT_NEAR(region_area(fills[0]), 120.0 * 100.0, 1e-2);
}

// A plate many orders of magnitude larger than the view (its corners far past any integer
// range of the polygon clipper at 1/1024 px) still fills exactly the image.
TEST(VisibleFills, HugeFacesAreCutBeforeClipping) {
    Mesh m;
    add_quad(m, {0.0f, 0.0f, 0.0f}, 1.0e6f, 0);
    const auto fills = visible_fills(m, ortho_camera(1.0e-9f), 100, 100, std::nullopt, glm::vec3(1.0f));
    ASSERT_EQ(fills.size(), 1u);
    EXPECT_NEAR(region_area(fills[0]), 100.0 * 100.0, 1e-2);
}

// A section plane through the centre, cutting away the half towards the camera: the inside
// of the far half shows, the whole disc of the sphere's radius (orthographic).
TEST(VisibleFills, SectionOpensTheSphere) {
    const Mesh sphere = builtin::sphere(64, 128, 1.0f);
    const SectionPlane front{.point = glm::vec3(0.0f), .normal = glm::vec3(0.0f, 0.0f, 1.0f)};
    const auto fills = visible_fills(sphere, ortho_camera(4.0f), 200, 200, front, glm::vec3(1.0f));
    ASSERT_EQ(fills.size(), 1u);
    const double radius = 50.0;  // 1 unit at 50 px a unit
    EXPECT_NEAR(region_area(fills[0]) / (kPi * radius * radius), 1.0, 0.01);
    // A plane that removes everything leaves nothing.
    const SectionPlane all{.point = glm::vec3(0.0f, 0.0f, -2.0f), .normal = glm::vec3(0.0f, 0.0f, 1.0f)};
    EXPECT_TRUE(visible_fills(sphere, ortho_camera(4.0f), 200, 200, all, glm::vec3(1.0f)).empty());
}

}  // namespace
}  // namespace inkshade::geometry
