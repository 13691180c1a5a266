// loose: a file's line primitives (OBJ `l`, glTF LINES) drawn with exact visibility against the
// surfaces. A box [-1, 1]^3 seen from (0, 0, 6): a line in front of it (z = 2) is drawn whole,
// a short one behind it (z = -2) not at all, and a long one behind it only where the ray from
// the eye misses the box (a slab test, Kay & Kajiya 1986).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/loose_lines.hpp"
#include "geometry/visibility.hpp"
#include "inkshade/io.hpp"
#include "inkshade/line_drawing.hpp"
#include "io/gltf_files.hpp"
#include "support/temp_dir.hpp"

namespace inkshade {
namespace {

constexpr int kSize = 400;

// Box corners, then the lines' ends: front (2), behind (2), the long line behind (3, a polyline).
const std::vector<glm::vec3> kPoints = {
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1},   {-1, 1, -1},  {-1, -1, 1},      {1, -1, 1},      {1, 1, 1},      {-1, 1, 1},
    {-0.5, 0, 2}, {0.5, 0, 2}, {-0.5, 0.3, -2}, {0.5, 0.3, -2}, {-2, -0.5, -2}, {0, -0.5, -2}, {2, -0.5, -2}};
const int kQuads[6][4] = {{1, 4, 3, 2}, {5, 6, 7, 8}, {1, 2, 6, 5}, {4, 8, 7, 3}, {1, 5, 8, 4}, {2, 3, 7, 6}};

std::string box_and_lines_obj() {
    std::string obj;
    for (const glm::vec3& p : kPoints)
        obj += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    for (const auto& q : kQuads)
        obj += "f " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + " " +
               std::to_string(q[3]) + "\n";
    return obj + "l 9 10\nl 11 12\nl 13 14 15\n";
}

std::string box_and_lines_glb() {
    test::GltfBuilder g;
    std::vector<float> box, lines;
    for (int i = 0; i < 8; ++i) box.insert(box.end(), {kPoints[i].x, kPoints[i].y, kPoints[i].z});
    std::vector<uint32_t> indices;
    for (const auto& q : kQuads)
        for (int k : {0, 1, 2, 0, 2, 3}) indices.push_back(uint32_t(q[k] - 1));
    for (int i : {8, 9, 10, 11, 12, 13, 13, 14}) lines.insert(lines.end(), {kPoints[i].x, kPoints[i].y, kPoints[i].z});
    const int faces = g.mesh({{"POSITION", g.floats(box, "VEC3", 3)}}, g.data(indices, test::kUInt, 1, "SCALAR"));
    const int segments = g.mesh({{"POSITION", g.floats(lines, "VEC3", 3)}}, -1, -1, test::kLines);
    g.scene({g.node({{"mesh", faces}}), g.node({{"mesh", segments}})});
    return g.glb();
}

Camera front_camera() {
    Camera c;
    c.eye = glm::vec3(0.0f, 0.0f, 6.0f);
    c.target = glm::vec3(0.0f);
    c.fov_degrees = 35.0f;
    c.near_plane = 0.5f;
    c.far_plane = 20.0f;
    return c;
}

// Does the segment from the eye to p pass through the box [-1, 1]^3?
bool behind_box(const glm::dvec3& eye, const glm::dvec3& p) {
    double t0 = 0.0, t1 = 1.0;
    for (int k = 0; k < 3; ++k) {
        const double d = p[k] - eye[k];
        if (std::abs(d) < 1e-12) {
            if (std::abs(eye[k]) > 1.0) return false;
            continue;
        }
        double a = (-1.0 - eye[k]) / d, b = (1.0 - eye[k]) / d;
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a), t1 = std::min(t1, b);
    }
    return t0 < t1;
}

// The image length of the part of the line a–b not behind the box (10 000 steps).
double visible_image_length(const geometry::ImageProjection& view, const glm::vec3& a, const glm::vec3& b) {
    double length = 0.0;
    const int steps = 10000;
    for (int i = 0; i < steps; ++i) {
        const glm::vec3 p = glm::mix(a, b, (i + 0.5f) / steps);
        if (behind_box(glm::dvec3(view.camera().eye), glm::dvec3(p))) continue;
        const glm::dvec3 pa = view.project(glm::mix(a, b, float(i) / steps)),
                         pb = view.project(glm::mix(a, b, float(i + 1) / steps));
        length += std::hypot(pb.x - pa.x, pb.y - pa.y);
    }
    return length;
}

double path_length(const LinePath& path) {
    double length = 0.0;
    for (size_t i = 0; i + 1 < path.points.size(); ++i) length += glm::length(path.points[i + 1] - path.points[i]);
    return length;
}

void expect_front_drawn_behind_hidden(const Mesh& mesh) {
    ASSERT_EQ(mesh.line_segments.size(), 4u);
    const Camera camera = front_camera();
    LineExtractor extractor(mesh);
    const LineDrawing drawing = extractor.draw(camera, kSize, kSize, {{"loose", {{"hidden", {1.0f}}}}});
    ASSERT_EQ(drawing.layers.size(), 1u);
    const geometry::ImageProjection view(camera, kSize, kSize);
    // Sort the drawn paths by the line they lie on (its image row).
    const double front_row = view.project(kPoints[8]).y, short_row = view.project(kPoints[10]).y,
                 long_row = view.project(kPoints[12]).y;
    double front = 0.0, short_behind = 0.0, long_behind = 0.0;
    for (const LinePath& p : drawing.layers[0].visible) {
        ASSERT_FALSE(p.points.empty());
        const double row = p.points[0].y;
        (std::abs(row - front_row) < 0.5 ? front : std::abs(row - short_row) < 0.5 ? short_behind : long_behind) +=
            path_length(p);
        EXPECT_TRUE(std::abs(row - front_row) < 0.5 || std::abs(row - short_row) < 0.5 ||
                    std::abs(row - long_row) < 0.5);
    }
    EXPECT_NEAR(front, visible_image_length(view, kPoints[8], kPoints[9]), 0.5);
    EXPECT_EQ(short_behind, 0.0);
    const double long_expected = visible_image_length(view, kPoints[12], kPoints[14]);
    EXPECT_GT(long_expected, 40.0);  // the line's two ends reach out beside the box
    EXPECT_NEAR(long_behind, long_expected, 1.0);
    // The hidden parts are the short line and the long line's middle.
    double hidden = 0.0;
    for (const LinePath& p : drawing.layers[0].hidden) hidden += path_length(p);
    const double all = glm::length(glm::dvec2(view.project(kPoints[10]) - view.project(kPoints[11]))) +
                       glm::length(glm::dvec2(view.project(kPoints[12]) - view.project(kPoints[14])));
    EXPECT_NEAR(hidden, all - long_expected, 1.0);
}

TEST(LooseLines, ObjLinesBehindABoxAreHiddenAndInFrontAreDrawn) {
    test::TempDir dir;
    const Mesh mesh = load_mesh(dir.write("box.obj", box_and_lines_obj()));
    EXPECT_EQ(mesh.triangle_count(), 12u);
    expect_front_drawn_behind_hidden(mesh);
}

TEST(LooseLines, GltfLinesBehindABoxAreHiddenAndInFrontAreDrawn) {
    test::TempDir dir;
    expect_front_drawn_behind_hidden(load_mesh(dir.write("box.glb", box_and_lines_glb())));
}

TEST(LooseLines, SegmentsAreOnNoFaceAndChainAtSharedVertices) {
    test::TempDir dir;
    const Mesh mesh = load_mesh(dir.write("box.obj", box_and_lines_obj()));
    const std::vector<geometry::LineSegment> segments = geometry::extract_loose_lines(mesh);
    ASSERT_EQ(segments.size(), 4u);
    for (const geometry::LineSegment& s : segments) EXPECT_EQ(s.face, geometry::kNoFace);
    EXPECT_EQ(segments[2].edge_b, segments[3].edge_a);  // the polyline's middle vertex
}

}  // namespace
}  // namespace inkshade
