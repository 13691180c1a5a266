// clip-boundary: a plane through a torus's centre perpendicular to its axis (z) cuts it in two
// circles of radii R − r and R + r; the near plane cuts a sphere in a circle.
#include "geometry/plane_cuts.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {
namespace {

TEST(PlaneCuts, SectionThroughTorusCentreGivesTwoClosedCircles) {
    constexpr double R = 1.0, r = 0.4;
    const Mesh torus = builtin::torus(float(R), float(r), 128, 64);
    const SectionPlane plane{.point = {0.0f, 0.0f, 0.0f}, .normal = {0.0f, 0.0f, 1.0f}};
    const std::vector<LineSegment> segments = extract_plane_cut(torus, plane, 1);
    ASSERT_FALSE(segments.empty());
    const std::vector<Polyline> loops = chain_segments(segments);
    ASSERT_EQ(loops.size(), 2u);
    int inner = 0, outer = 0;
    for (const Polyline& loop : loops) {
        EXPECT_TRUE(loop.closed);
        const double first = glm::length(glm::dvec2(loop.points[0]));
        const double radius = first < R ? R - r : R + r;
        (first < R ? inner : outer)++;
        for (const glm::vec3& p : loop.points) {
            EXPECT_NEAR(p.z, 0.0, 1e-6);
            // The polygon's chords lie inside the circle by at most R(1 − cos(π / 128)).
            EXPECT_NEAR(glm::length(glm::dvec2(p)), radius, 5e-4);
        }
    }
    EXPECT_EQ(inner, 1);
    EXPECT_EQ(outer, 1);
}

TEST(PlaneCuts, NearPlaneCutsTheSphereInACircle) {
    const Mesh sphere = builtin::sphere(64, 128, 1.0f);
    Camera camera;
    camera.eye = {0.0f, 0.0f, 1.5f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.near_plane = 0.8f;  // the plane z = 0.7
    const SectionPlane near = near_plane_of(camera);
    EXPECT_NEAR(near.point.z, 0.7f, 1e-6f);
    EXPECT_NEAR(near.normal.z, 1.0f, 1e-6f);  // towards the eye: the clipped side
    const std::vector<Polyline> loops = chain_segments(extract_plane_cut(sphere, near, 0));
    ASSERT_EQ(loops.size(), 1u);
    EXPECT_TRUE(loops[0].closed);
    for (const glm::vec3& p : loops[0].points) {
        EXPECT_NEAR(p.z, 0.7, 1e-6);
        EXPECT_NEAR(glm::length(glm::dvec2(p)), std::sqrt(1.0 - 0.49), 2e-3);
    }
    // Drawn, the whole circle is visible (rays start at the near plane, as GL clips) and closed.
    LineExtractor extractor(sphere);
    const LineDrawing drawing = extractor.draw(camera, 200, 200, {{"clip-boundary", {}}});
    ASSERT_EQ(drawing.layers[0].visible.size(), 1u);
    EXPECT_TRUE(drawing.layers[0].visible[0].closed);
}

double total_length(const std::vector<LinePath>& paths) {
    double length = 0.0;
    for (const LinePath& p : paths)
        for (size_t k = 0; k + 1 < p.points.size() + (p.closed ? 1 : 0); ++k)
            length += glm::length(p.points[(k + 1) % p.points.size()] - p.points[k]);
    return length;
}

// Seen from above, the section removes the torus's upper half (the normal's side): its two cut
// circles are the rims of the open lower half and show whole, but for a pixel or two where a
// rim is seen edge-on, behind the kept faces that straddle the plane. With the whole mesh the
// near halves would lie inside it, hidden; without a plane there is no cut at all.
TEST(PlaneCuts, SectionPlaneOpensTheModelInTheDrawing) {
    const Mesh torus = builtin::torus(1.0f, 0.4f, 64, 32);
    Camera camera;
    camera.eye = {0.0f, -5.0f, 4.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.up = {0.0f, 0.0f, 1.0f};
    camera.near_plane = 0.5f;
    LineExtractor extractor(torus);
    const std::vector<LineSettings> lines = {{"clip-boundary", {{"hidden", {1.0f}}}}, {"contour", {}}};
    const LineDrawing none = extractor.draw(camera, 200, 200, lines);
    EXPECT_TRUE(none.layers[0].visible.empty() && none.layers[0].hidden.empty());
    const LineContext section{.light = std::nullopt, .section = SectionPlane{{0, 0, 0}, {0, 0, 1}}};
    const LineDrawing cut = extractor.draw(camera, 200, 200, lines, nullptr, nullptr, section);
    const double visible = total_length(cut.layers[0].visible), hidden = total_length(cut.layers[0].hidden);
    EXPECT_GT(visible, 500.0);
    EXPECT_LT(hidden, 0.02 * visible) << "the cut is open to the camera";
    // The removed half's contour is gone: from above, the open lower half's outline is shorter
    // than the whole torus's contour.
    EXPECT_LT(total_length(cut.layers[1].visible), total_length(none.layers[1].visible));
}

}  // namespace
}  // namespace inkshade::geometry
