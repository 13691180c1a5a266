#include "inkshade/line_drawing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/builtin_models.hpp"
#include "inkshade/error.hpp"

namespace inkshade {
namespace {

constexpr int kWidth = 320, kHeight = 240;  // not square: the aspect must be handled

LineSettings contour_with_hidden() { return {"contour", {{"hidden", {1.0f}}}}; }

Camera looking_at_origin(const glm::vec3& eye, bool orthographic) {
    Camera c;
    c.eye = eye;
    c.target = glm::vec3(0.0f);
    c.up = glm::vec3(0, 1, 0);
    c.fov_degrees = 35.0f;
    c.orthographic = orthographic;
    c.ortho_height = 2.6f;
    c.near_plane = 0.5f;
    c.far_plane = 20.0f;
    return c;
}

// Radius in pixels of the outline of a sphere of radius r at the origin seen from `camera`
// (looking at its centre): the tangent cone has half-angle asin(r / d), so the outline is the
// circle of NDC radius tan(asin(r / d)) / tan(fov / 2); orthographic: r / (ortho_height / 2).
double outline_radius_px(const Camera& camera, double r) {
    const double half_h = 0.5 * kHeight;
    if (camera.orthographic) return r / (0.5 * camera.ortho_height) * half_h;
    const double d = glm::length(glm::dvec3(camera.eye));
    return std::tan(std::asin(r / d)) / std::tan(glm::radians(0.5 * camera.fov_degrees)) * half_h;
}

void expect_contour_is_circle(const Camera& camera) {
    const Mesh sphere = builtin::sphere();
    LineExtractor extractor(sphere);
    const LineDrawing drawing = extractor.draw(camera, kWidth, kHeight, {contour_with_hidden()});
    ASSERT_EQ(drawing.layers.size(), 1u);
    const LineLayer& layer = drawing.layers[0];
    ASSERT_EQ(layer.visible.size(), 1u) << "the whole outline is one polyline";
    EXPECT_TRUE(layer.visible[0].closed);
    EXPECT_TRUE(layer.hidden.empty()) << "no part of a sphere's outline is behind the sphere";
    const double radius = outline_radius_px(camera, 1.0);
    const glm::dvec2 centre(0.5 * kWidth, 0.5 * kHeight);
    double worst = 0.0;
    for (const glm::vec2& p : layer.visible[0].points)
        worst = std::max(worst, std::abs(glm::length(glm::dvec2(p) - centre) - radius));
    EXPECT_LT(worst, 0.5) << "radius " << radius << " px";
    EXPECT_GT(layer.visible[0].points.size(), 64u);
    for (float d : layer.visible[0].depth) {
        EXPECT_GT(d, 0.0f);
        EXPECT_LT(d, 1.0f);
    }
}

TEST(LineDrawing, SphereContourIsCirclePerspective) {
    expect_contour_is_circle(looking_at_origin({0.0f, 0.0f, 4.0f}, false));
    expect_contour_is_circle(looking_at_origin({2.0f, 1.5f, 3.0f}, false));  // oblique: still a circle
}

TEST(LineDrawing, SphereContourIsCircleOrthographic) {
    expect_contour_is_circle(looking_at_origin({0.0f, 0.0f, 4.0f}, true));
    expect_contour_is_circle(looking_at_origin({-1.0f, 2.5f, 2.0f}, true));
}

TEST(LineDrawing, NoSuggestiveContoursOnSphere) {
    // κr = 1/r > 0 everywhere on a sphere: no zeros, no suggestive contours.
    const Mesh sphere = builtin::sphere();
    LineExtractor extractor(sphere);
    const LineDrawing drawing = extractor.draw(looking_at_origin({1.0f, 1.0f, 3.5f}, false), kWidth, kHeight,
                                               {{"suggestive", {{"threshold", {0.0f}}}}});
    ASSERT_EQ(drawing.layers.size(), 1u);
    EXPECT_TRUE(drawing.layers[0].visible.empty());
}

TEST(LineDrawing, TorusHasSuggestiveContoursAndSphereHasNoCreasesOrBorders) {
    const Mesh torus = builtin::torus();
    LineExtractor extractor(torus);
    Camera camera = looking_at_origin({0.0f, -3.5f, 2.5f}, false);
    camera.up = glm::vec3(0, 0, 1);
    const LineDrawing t = extractor.draw(camera, kWidth, kHeight, {{"suggestive", {}}, {"contour", {}}});
    ASSERT_EQ(t.layers.size(), 2u);
    EXPECT_EQ(t.layers[0].settings.type, "suggestive");  // the caller's order
    EXPECT_FALSE(t.layers[0].visible.empty()) << "the inner, saddle-shaped half of a torus has κr = 0 lines";

    const Mesh sphere = builtin::sphere();
    LineExtractor s(sphere);
    const LineDrawing d = s.draw(camera, kWidth, kHeight, {{"crease", {}}, {"border", {}}});
    ASSERT_EQ(d.layers.size(), 2u);
    EXPECT_TRUE(d.layers[0].visible.empty());
    EXPECT_TRUE(d.layers[1].visible.empty());
}

TEST(LineDrawing, MinLengthDropsShortPolylines) {
    const Mesh sphere = builtin::sphere();
    LineExtractor extractor(sphere);
    const Camera camera = looking_at_origin({0.0f, 0.0f, 4.0f}, false);
    const double circumference = 2.0 * M_PI * outline_radius_px(camera, 1.0);
    auto count = [&](float min_length) {
        return extractor.draw(camera, kWidth, kHeight, {{"contour", {{"min-length", {min_length}}}}})
            .layers[0]
            .visible.size();
    };
    EXPECT_EQ(count(float(circumference) - 5.0f), 1u);
    EXPECT_EQ(count(float(circumference) + 5.0f), 0u);
}

// The layer's stroke parameters finish the drawing: the sphere's outline (a circle of known
// length) dashed 20 on, 10 off, and with depth widths every point of a circle seen head-on at
// the sphere's middle depth gets the middle factor.
TEST(LineDrawing, StrokeParametersFinishTheLayer) {
    const Mesh sphere = builtin::sphere();
    LineExtractor extractor(sphere);
    const Camera camera = looking_at_origin({0.0f, 0.0f, 4.0f}, true);
    const double circumference = 2.0 * M_PI * outline_radius_px(camera, 1.0);
    const LineDrawing dashed = extractor.draw(camera, kWidth, kHeight, {{"contour", {{"dash", {20.0f, 10.0f}}}}});
    const std::vector<LinePath>& dashes = dashed.layers[0].visible;
    ASSERT_EQ(dashes.size(), size_t(std::ceil(circumference / 30.0)));
    double on = 0.0;
    for (const LinePath& d : dashes) {
        double len = 0.0;
        for (size_t i = 1; i < d.points.size(); ++i) len += glm::length(glm::dvec2(d.points[i] - d.points[i - 1]));
        EXPECT_LE(len, 20.0 + 1e-3);
        EXPECT_FALSE(d.closed);
        on += len;
    }
    EXPECT_NEAR(on, circumference * 2.0 / 3.0, 20.0);
    // Orthographic, looking down -z at a unit sphere: its outline lies at the centre's depth,
    // half way between the nearest and farthest point, so width 2 × mix(3, 1, 0.5) = 4.
    const LineDrawing wide =
        extractor.draw(camera, kWidth, kHeight, {{"contour", {{"width", {2.0f}}, {"depth-width", {3.0f, 1.0f}}}}});
    ASSERT_EQ(wide.layers[0].visible.size(), 1u);
    const LinePath& outline = wide.layers[0].visible[0];
    ASSERT_EQ(outline.width.size(), outline.points.size());
    for (float w : outline.width) EXPECT_NEAR(w, 4.0f, 0.02f);
    EXPECT_TRUE(outline.color.empty());
    EXPECT_THROW(extractor.draw(camera, kWidth, kHeight, {{"contour", {{"dash", {0.5f}}}}}), InputError);
}

TEST(LineDrawing, RepeatedDrawsAreIdenticalAndReportTimings) {
    const Mesh torus = builtin::torus();
    LineExtractor extractor(torus);
    const Camera camera = looking_at_origin({1.0f, -3.0f, 2.0f}, false);
    std::vector<LineTiming> first, second;
    const LineDrawing a = extractor.draw(camera, kWidth, kHeight, {contour_with_hidden()}, &first);
    const LineDrawing b = extractor.draw(camera, kWidth, kHeight, {contour_with_hidden()}, &second);
    ASSERT_EQ(a.layers[0].visible.size(), b.layers[0].visible.size());
    for (size_t i = 0; i < a.layers[0].visible.size(); ++i)
        EXPECT_EQ(a.layers[0].visible[i].points, b.layers[0].visible[i].points);
    auto has = [](const std::vector<LineTiming>& t, const std::string& stage) {
        for (const auto& x : t)
            if (x.stage == stage) return true;
        return false;
    };
    EXPECT_TRUE(has(first, "ray scene"));    // built once per mesh ...
    EXPECT_FALSE(has(second, "ray scene"));  // ... and kept
    for (const char* stage : {"extract", "visibility", "chain", "finish"}) EXPECT_TRUE(has(second, stage)) << stage;
}

// The stages in the order --timing prints them: the mesh-wide work first (its own stages), then
// per view extract, visibility, chain, finish and, in a sequence, coherence.
TEST(LineDrawing, TimingStagesComeInPipelineOrder) {
    const Mesh torus = builtin::torus();
    LineExtractor extractor(torus);
    const Camera camera = looking_at_origin({1.0f, -3.0f, 2.0f}, false);
    const std::vector<LineSettings> lines{{"contour", {{"coherence", {1.0f}}}}, {"crease", {}}, {"suggestive", {}}};
    StrokeSequence sequence;
    std::vector<LineTiming> first, second;
    extractor.draw(camera, kWidth, kHeight, lines, &first, &sequence);
    extractor.draw(camera, kWidth, kHeight, lines, &second, &sequence);
    std::vector<std::string> stages;
    for (const LineTiming& t : second) stages.push_back(t.stage);
    EXPECT_EQ(stages, (std::vector<std::string>{"extract", "visibility", "chain", "finish", "coherence"}));
    std::vector<std::string> once;
    for (const LineTiming& t : first) once.push_back(t.stage);
    ASSERT_GE(once.size(), 5u);
    EXPECT_EQ(std::vector<std::string>(once.end() - 5, once.end()), stages);
    for (const char* stage : {"curvature", "adjacency", "creases", "ray scene"})
        EXPECT_NE(std::find(once.begin(), once.end() - 5, stage), once.end() - 5) << stage;
}

TEST(LineDrawing, BadSizeAndUnknownTypeAreInputErrors) {
    const Mesh sphere = builtin::sphere(8, 16);
    LineExtractor extractor(sphere);
    const Camera camera = looking_at_origin({0.0f, 0.0f, 4.0f}, false);
    EXPECT_THROW(extractor.draw(camera, 0, 10, {{"contour", {}}}), InputError);
    EXPECT_THROW(extractor.draw(camera, 10, 10, {{"scribbles", {}}}), InputError);
}

TEST(LineDrawing, EmptyMeshGivesEmptyLayersAndBrokenFacesOnlyFiniteLines) {
    Mesh empty;
    LineExtractor e(empty);
    const Camera camera = looking_at_origin({0.0f, 0.0f, 4.0f}, false);
    const LineDrawing none = e.draw(camera, 64, 64, {{"contour", {}}, {"border", {}}});
    ASSERT_EQ(none.layers.size(), 2u);
    for (const LineLayer& layer : none.layers) {
        EXPECT_TRUE(layer.visible.empty()) << layer.settings.type;
        EXPECT_TRUE(layer.hidden.empty()) << layer.settings.type;
    }

    // Repeated indices, a zero-area face, an out-of-range index and a non-manifold fan.
    Mesh bad;
    bad.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {2, 2, 2}};
    bad.triangles = {{0, 1, 2}, {0, 0, 1}, {3, 4, 5}, {0, 1, 99}, {0, 1, 3}, {0, 1, 4}};
    LineExtractor b(bad);
    const LineDrawing d =
        b.draw(camera, 64, 64, {{"contour", {{"silhouette-edges", {1.0f}}}}, {"crease", {}}, {"border", {}}});
    ASSERT_EQ(d.layers.size(), 3u);
    const char* types[] = {"contour", "crease", "border"};
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(d.layers[i].settings.type, types[i]);
        for (const LinePath& p : d.layers[i].visible)
            for (const glm::vec2& q : p.points) EXPECT_TRUE(std::isfinite(q.x) && std::isfinite(q.y)) << types[i];
    }
    // The faces that are triangles still have their open edges: (1, 2), (2, 0) of the first
    // face and the lone face (3, 4, 5) face the camera.
    EXPECT_FALSE(d.layers[2].visible.empty());
}

}  // namespace
}  // namespace inkshade
