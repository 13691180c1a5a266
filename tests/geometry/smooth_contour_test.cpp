// The smooth contour of a coarse CAD part (issue 33 item 2: fandisk with --smooth-angle 180).
// rtsc draws the zero crossings of n·v on per-vertex normals averaged across every edge, sharp
// or not; on a coarse part that line wanders well inside the faces next to a crease, so any
// change of the normals (weights, welding, a split), of the extraction or of what is dropped as
// short moves it by pixels. This test computes the line itself (Thürmer & Wüthrich 1998 angle
// weights, Inkshade's documented default; trimesh2's need_normals weights differ on such a
// part) and holds every level of the drawn contour, visible and hidden, to it within a pixel
// both ways. What is drawn as visible is visibility's business (docs/benchmarks.md, "fandisk's
// smooth contour against rtsc").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <sstream>

#include "analytic_meshes.hpp"
#include "geometry/builtin_models.hpp"
#include "geometry/depth_reference.hpp"
#include "geometry/rtsc_depth_buffer.hpp"
#include "geometry/visibility.hpp"
#include "inkshade/io.hpp"
#include "inkshade/line_drawing.hpp"
#include "support/off_text.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::geometry {
namespace {

// Angle-weighted vertex normals, computed here in double (not with src/geometry/normals.cpp).
std::vector<glm::dvec3> angle_weighted_normals(const Mesh& m) {
    std::vector<glm::dvec3> sum(m.positions.size(), glm::dvec3(0.0));
    for (const glm::uvec3& t : m.triangles) {
        const glm::dvec3 p[3] = {glm::dvec3(m.positions[t.x]), glm::dvec3(m.positions[t.y]),
                                 glm::dvec3(m.positions[t.z])};
        const glm::dvec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 u = glm::normalize(p[(k + 1) % 3] - p[k]), w = glm::normalize(p[(k + 2) % 3] - p[k]);
            sum[t[k]] += std::acos(std::clamp(glm::dot(u, w), -1.0, 1.0)) * n;
        }
    }
    for (glm::dvec3& n : sum) n = glm::normalize(n);
    return sum;
}

// The contour's image points every half pixel: per face, the segment between the zero crossings
// of n·v (view vector towards the eye) on its two edges whose ends differ in sign.
std::vector<glm::dvec2> reference_contour(const Mesh& m, const std::vector<glm::dvec3>& normals,
                                          const ImageProjection& view) {
    const glm::dvec3 eye(view.camera().eye);
    std::vector<double> g(m.positions.size());
    for (size_t v = 0; v < g.size(); ++v) g[v] = glm::dot(normals[v], glm::normalize(eye - glm::dvec3(m.positions[v])));
    std::vector<glm::dvec2> out;
    for (const glm::uvec3& t : m.triangles) {
        std::vector<glm::dvec3> ends;
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = t[k], b = t[(k + 1) % 3];
            if ((g[a] >= 0.0) == (g[b] >= 0.0)) continue;
            const double s = g[a] / (g[a] - g[b]);
            ends.push_back(glm::dvec3(m.positions[a]) + s * (glm::dvec3(m.positions[b]) - glm::dvec3(m.positions[a])));
        }
        if (ends.size() != 2) continue;
        const glm::dvec3 pa = view.project(glm::vec3(ends[0])), pb = view.project(glm::vec3(ends[1]));
        const int steps = std::max(1, int(glm::length(glm::dvec2(pb) - glm::dvec2(pa)) / 0.5));
        for (int i = 0; i <= steps; ++i) {
            const glm::dvec3 p = ends[0] + (double(i) / steps) * (ends[1] - ends[0]);
            out.push_back(glm::dvec2(view.project(glm::vec3(p))));
        }
    }
    return out;
}

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 d = b - a;
    const double len2 = glm::dot(d, d);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * d));
}

// Share of `points` within `tolerance` pixels of some segment of `paths`.
double share_near(const std::vector<glm::dvec2>& points, const std::vector<const LinePath*>& paths, double tolerance) {
    size_t near = 0;
    for (const glm::dvec2& p : points) {
        bool hit = false;
        for (const LinePath* path : paths) {
            const size_t n = path->points.size();
            for (size_t i = 0; i + 1 < n + (path->closed ? 1 : 0) && !hit; ++i)
                hit = distance_to_segment(p, glm::dvec2(path->points[i]), glm::dvec2(path->points[(i + 1) % n])) <=
                      tolerance;
            if (hit) break;
        }
        near += hit;
    }
    return points.empty() ? 0.0 : double(near) / double(points.size());
}

TEST(SmoothContour, CoarseCadPartDrawsTheVertexNormalsZeroCrossings) {
    const Mesh part = test::capped_cylinder(1.0f, 12, 2.0f);  // 30° between sides, 90° to the caps
    test::TempDir dir;
    LoadOptions options;
    options.smooth_angle = 180.0f;  // rtsc's normals: averaged across every edge
    const Mesh loaded = load_mesh(dir.write("part.off", test::off_text(part)), options);
    ASSERT_FALSE(loaded.has_hard_edges());
    const std::vector<glm::dvec3> normals = angle_weighted_normals(part);

    LineExtractor extractor(loaded);
    const int size = 400;
    for (const glm::vec3 eye :
         {glm::vec3(4.0f, 3.0f, 5.0f), glm::vec3(-5.0f, 1.0f, 0.5f), glm::vec3(1.0f, -6.0f, 3.0f)}) {
        Camera camera;
        camera.eye = eye;
        camera.target = {0.0f, 0.0f, 1.0f};
        camera.up = {0.0f, 0.0f, 1.0f};
        const LineDrawing drawing =
            extractor.draw(camera, size, size, {{"contour", {{"hidden", {1.0f}}, {"min-length", {0.0f}}}}});
        ASSERT_EQ(drawing.layers.size(), 1u);
        std::vector<const LinePath*> drawn;
        std::vector<glm::dvec2> drawn_points;
        for (const auto* list : {&drawing.layers[0].visible, &drawing.layers[0].hidden})
            for (const LinePath& path : *list) {
                drawn.push_back(&path);
                for (const glm::vec2& p : path.points) drawn_points.push_back(glm::dvec2(p));
            }
        const std::vector<glm::dvec2> reference = reference_contour(part, normals, ImageProjection(camera, size, size));
        ASSERT_GT(reference.size(), 200u);
        // Built as a polyline of the reference's own half-pixel samples, per face.
        std::vector<LinePath> reference_paths;
        for (size_t i = 0; i + 1 < reference.size(); ++i)
            if (glm::length(reference[i + 1] - reference[i]) < 0.75)
                reference_paths.push_back({.points = {glm::vec2(reference[i]), glm::vec2(reference[i + 1])}});
        std::vector<const LinePath*> reference_lines;
        for (const LinePath& path : reference_paths) reference_lines.push_back(&path);
        EXPECT_GE(share_near(reference, drawn, 1.0), 0.99) << "eye " << eye.x << " " << eye.y << " " << eye.z;
        EXPECT_GE(share_near(drawn_points, reference_lines, 1.0), 0.99)
            << "eye " << eye.x << " " << eye.y << " " << eye.z;
    }
}

// The visible contour against rtsc's depth test (tests/geometry/rtsc_depth_buffer.hpp) over
// all levels of the same extraction, from eight views around the part at 1024².
// `drawn`: a second load of the mesh (the default auto-smooth) whose visible contour is
// compared with rtsc's drawing of `mesh` (docs/benchmarks.md); none: mesh's own.
test::RtscAgreement agreement_with_rtsc(const Mesh& mesh, float elevation_step = 0.0f, const Mesh* drawn = nullptr) {
    LineExtractor extractor(mesh);
    std::optional<LineExtractor> drawn_extractor;
    if (drawn) drawn_extractor.emplace(*drawn);
    test::RtscAgreement sum;
    for (int k = 0; k < 8; ++k) {
        CameraOptions options;
        options.azimuth_degrees = 45.0f * float(k) + 10.0f;
        options.elevation_degrees = 25.0f + elevation_step * float(k % 3);
        const int size = 1024;
        const Camera camera = frame_camera(mesh.bounds(), options, 1.0f, mesh.positions);
        const LineDrawing drawing = extractor.draw(camera, size, size, {{"contour", {{"hidden", {1.0f}}}}});
        const std::optional<LineDrawing> other =
            drawn ? std::optional(drawn_extractor->draw(camera, size, size, {{"contour", {}}})) : std::nullopt;
        const test::RtscAgreement a = test::rtsc_agreement(test::RtscDepthBuffer(mesh, camera, size, size),
                                                           drawing.layers.at(0), 2.0,
                                                           other ? &other->layers.at(0) : nullptr);
        std::printf("[ measure  ] view %d: recall %.3f precision %.3f (rtsc %.0f px, visible %.0f px)\n", k, a.recall(),
                    a.precision(), a.rtsc_visible, a.visible);
        sum += a;
    }
    return sum;
}

TEST(SmoothContour, CoarseCadPartIsVisibleWhereRtscDrawsIt) {
    // A thin plate and a thin disc, normals averaged across every edge: a rim vertex's normal
    // leans half towards the top, so the contour runs a little way down the back-facing rim
    // face, behind the top face's edge by a pixel or two of depth. rtsc draws it there (its
    // mesh pushed back by glPolygonOffset(5, 30)), and so does the slope allowance of a
    // contour's own faces (docs/lines.md, Visibility); a plain own-surface rule hides it.
    test::TempDir dir;
    LoadOptions options;
    options.smooth_angle = 180.0f;
    for (const auto& [name, part] : {std::pair{"plate", test::box({-1.0f, -0.02f, -1.0f}, {1.0f, 0.02f, 1.0f})},
                                     std::pair{"disc", test::capped_cylinder(1.0f, 24, 0.05f)}}) {
        const Mesh loaded = load_mesh(dir.write(std::string(name) + ".off", test::off_text(part)), options);
        const test::RtscAgreement a = agreement_with_rtsc(loaded, 10.0f);
        EXPECT_GE(a.recall(), 0.97) << name << ": " << a.rtsc_visible << " px rtsc draws";
        EXPECT_GE(a.precision(), 0.98) << name << ": " << a.visible << " px visible";
        EXPECT_GT(a.visible, 4000.0) << name;
    }
}

TEST(SmoothContour, CoarseSphereOutlineIsWhole) {
    // A 16 x 32 UV sphere with its exact normals, alone: nothing hides its contour, which runs
    // along the polygon outline up to a segment's sagitta (1.8 px here) behind the faces next to
    // it, at a grazing angle. The circle is drawn as rtsc draws it: all but a few short gaps
    // where a grazing ray meets a face of the next ring tens of pixels of depth in front (2-5 %
    // of the circle; about 25 % with the own-surface rule alone).
    const Mesh sphere = builtin::sphere(16, 32, 1.0f);
    ASSERT_FALSE(sphere.normals.empty());
    LineExtractor extractor(sphere);
    const int size = 1024;
    for (const glm::vec3 eye : {glm::vec3(0.0f, 1.0f, 5.0f), glm::vec3(3.0f, 2.5f, 3.0f)}) {
        Camera camera;
        camera.eye = eye;
        camera.fov_degrees = 30.0f;
        camera.near_plane = 0.5f;
        camera.far_plane = 20.0f;
        const LineDrawing drawing = extractor.draw(camera, size, size, {{"contour", {{"hidden", {1.0f}}}}});
        const LineLayer& layer = drawing.layers.at(0);
        // The silhouette of a unit sphere seen from distance D: a circle of angular radius
        // asin(1 / D), tan of it times the focal length in pixels.
        const double focal = 0.5 * size / std::tan(glm::radians(0.5 * double(camera.fov_degrees)));
        const double radius = focal * std::tan(std::asin(1.0 / double(glm::length(eye))));
        double visible = 0.0, hidden = 0.0, off = 0.0;
        for (const auto* list : {&layer.visible, &layer.hidden})
            test::for_each_sample(*list, 0.25, [&](glm::dvec2 p, double, double length, const LinePath&) {
                (list == &layer.visible ? visible : hidden) += length;
                off = std::max(off, std::abs(glm::length(p - glm::dvec2(0.5 * size)) - radius));
            });
        const double circle = 2.0 * std::numbers::pi * radius;
        EXPECT_GE(visible, 0.93 * circle);
        EXPECT_LE(visible + hidden, 1.08 * circle) << "the polygon outline zigzags a little";
        EXPECT_LE(hidden, 0.06 * circle);
        EXPECT_LT(off, 4.5) << "px from the analytic circle: the sagitta of a quad's diagonal";
    }
}

// INKSHADE_RTSC_MESHES=FILE[;FILE...]: each mesh loaded with --smooth-angle 180 (rtsc's
// normals), its visible contour against rtsc's depth test; then the visible contour of the
// default load (auto-smooth: hard-edge contours too) against that same rtsc drawing. Skipped
// without it (the parts are not in the repository); docs/benchmarks.md has the figures.
TEST(SmoothContour, RtscAgreementOfMeshesFromEnvironment) {
    const char* list = std::getenv("INKSHADE_RTSC_MESHES");
    if (!list || !*list) GTEST_SKIP() << "INKSHADE_RTSC_MESHES not set";
    std::stringstream files(list);
    for (std::string file; std::getline(files, file, ';');) {
        LoadOptions options;
        options.smooth_angle = 180.0f;
        const Mesh smooth = load_mesh(file, options), by_default = load_mesh(file);
        const test::RtscAgreement a = agreement_with_rtsc(smooth, 5.0f);
        std::printf("[ measure  ] %s: recall %.3f precision %.3f\n", file.c_str(), a.recall(), a.precision());
        const test::RtscAgreement d = agreement_with_rtsc(smooth, 5.0f, &by_default);
        std::printf("[ measure  ] %s, default load: recall %.3f precision %.3f\n", file.c_str(), d.recall(),
                    d.precision());
    }
}

}  // namespace
}  // namespace inkshade::geometry
