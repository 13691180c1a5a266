// Line sets select exactly the faces they name (issue 34): face selections on a mesh, the
// segments they keep, and a drawing's line sets against the drawing of every face.
#include <gtest/gtest.h>

#include <numeric>

#include "geometry/analytic_meshes.hpp"
#include "geometry/face_selection.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade {
namespace {

using geometry::SelectedFaces;

// Cube A (object "A", material "steel", half size 1 at x = -1.5, z = -2) behind cube B ("B",
// "paint", half size 0.6 at x = -0.6): B hides part of A from a camera on +z. B's +y side (its
// faces 6 and 7 of 12) is face-marked 1.
Mesh two_parts() {
    Mesh m;
    m.materials = {Material{"steel"}, Material{"paint"}};
    m.object_names = {"A", "B"};
    for (int part = 0; part < 2; ++part) {
        Mesh c = test::cube(part == 0 ? 1.0f : 0.6f);
        const glm::vec3 at = part == 0 ? glm::vec3(-1.5f, 0.0f, -2.0f) : glm::vec3(-0.6f, 0.0f, 0.0f);
        const auto base = uint32_t(m.positions.size());
        for (const glm::vec3& p : c.positions) m.positions.push_back(p + at);
        for (size_t f = 0; f < c.triangles.size(); ++f) {
            m.triangles.push_back(c.triangles[f] + glm::uvec3(base));
            m.face_materials.push_back(uint32_t(part));
            m.face_objects.push_back(uint32_t(part));
            m.face_marks.push_back(part == 1 && (f == 6 || f == 7) ? 1 : 0);
        }
    }
    return m;
}

size_t count(const std::vector<uint8_t>& v) { return size_t(std::accumulate(v.begin(), v.end(), 0)); }

TEST(LineSets, GlobMatchesWholeNames) {
    EXPECT_TRUE(glob_match("steel", "steel"));
    EXPECT_TRUE(glob_match("st*", "steel"));
    EXPECT_TRUE(glob_match("*l", "steel"));
    EXPECT_TRUE(glob_match("s?e*l", "steel"));
    EXPECT_TRUE(glob_match("*", ""));
    EXPECT_TRUE(glob_match("a*b*c", "aXbYbZc"));
    EXPECT_FALSE(glob_match("st", "steel"));
    EXPECT_FALSE(glob_match("Steel", "steel"));  // names in files are case-sensitive
    EXPECT_FALSE(glob_match("?", ""));
    EXPECT_FALSE(glob_match("a*b", "aXbY"));
}

TEST(LineSets, SelectionsTakeExactlyTheNamedFaces) {
    const Mesh m = two_parts();
    const std::vector<uint8_t> steel = geometry::selected_faces(m, {.materials = {"st*"}});
    EXPECT_EQ(count(steel), 12u);
    for (size_t f = 0; f < 12; ++f) EXPECT_EQ(steel[f], 1) << f;
    const std::vector<uint8_t> b = geometry::selected_faces(m, {.objects = {"X", "B"}});
    EXPECT_EQ(count(b), 12u);
    EXPECT_EQ(b[12], 1);
    const std::vector<uint8_t> marked = geometry::selected_faces(m, {.face_mark = -1});
    EXPECT_EQ(count(marked), 2u);
    EXPECT_EQ(marked[18] + marked[19], 2);
    EXPECT_EQ(count(geometry::selected_faces(m, {.face_mark = 2})), 0u);
    EXPECT_EQ(count(geometry::selected_faces(m, {.face_mark = 0})), 22u);
    // Every criterion must match: B's faces that are marked; inverted, all the others.
    EXPECT_EQ(count(geometry::selected_faces(m, {.objects = {"B"}, .face_mark = -1})), 2u);
    EXPECT_EQ(count(geometry::selected_faces(m, {.objects = {"A"}, .face_mark = -1})), 0u);
    EXPECT_EQ(count(geometry::selected_faces(m, {.objects = {"B"}, .face_mark = -1, .invert = true})), 22u);
    // A mesh without names: "" is every face's name.
    Mesh bare = test::cube();
    EXPECT_EQ(count(geometry::selected_faces(bare, {.objects = {"*"}})), 12u);
    EXPECT_EQ(count(geometry::selected_faces(bare, {.materials = {"steel"}})), 0u);
}

TEST(LineSets, SegmentsAlongAnEdgeAreKeptWhenEitherFaceIsSelected) {
    // Two triangles meeting along (1, 2), the second with its own copies of those vertices (a
    // seam): the segment's face is the first, only the second is selected.
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    m.triangles = {{0, 1, 2}, {3, 5, 4}};
    m.face_marks = {0, 1};
    const SelectedFaces marked(m, {.face_mark = -1});
    geometry::LineSegment along{.a = m.positions[1], .b = m.positions[2]};
    along.edge_a = geometry::vertex_key(1);
    along.edge_b = geometry::vertex_key(2);
    along.face = 0;
    EXPECT_TRUE(marked.keeps(along));
    // Across face 0 (a contour's segment): face 0 alone decides.
    geometry::LineSegment across = along;
    across.edge_a = geometry::edge_key(0, 1);
    across.edge_b = geometry::edge_key(0, 2);
    EXPECT_FALSE(marked.keeps(across));
    across.face_b = 1;  // an intersection line lies on both faces
    EXPECT_TRUE(marked.keeps(across));
    // An edge of face 0 alone is not kept.
    geometry::LineSegment other = along;
    other.edge_b = geometry::vertex_key(0);
    EXPECT_FALSE(marked.keeps(other));
}

Camera front_camera() {
    Camera c;
    c.eye = {0.0f, 1.5f, 6.0f};
    c.target = {-0.5f, 0.0f, -1.0f};
    c.up = {0, 1, 0};
    c.fov_degrees = 40.0f;
    c.near_plane = 0.5f;
    c.far_plane = 30.0f;
    return c;
}

double total_length(const LineLayer& layer) {
    double sum = 0.0;
    for (const auto* paths : {&layer.visible, &layer.hidden})
        for (const LinePath& p : *paths)
            for (size_t i = 0; i + 1 < p.points.size(); ++i) sum += double(glm::length(p.points[i + 1] - p.points[i]));
    return sum;
}

LineSettings crease_of(const std::string& set, FaceSelection faces) {
    return {"crease", {{"smooth", {0.0f}}, {"min-length", {0.0f}}}, set, std::move(faces)};
}

TEST(LineSets, EachSetDrawsItsFacesLinesWithTheWholeMeshHidingThem) {
    LineExtractor extractor(two_parts());
    const Camera camera = front_camera();
    const LineDrawing all = extractor.draw(camera, 400, 300, {crease_of("", {})});
    const LineDrawing sets =
        extractor.draw(camera, 400, 300, {crease_of("A", {.objects = {"A"}}), crease_of("B", {.objects = {"B"}})});
    ASSERT_EQ(sets.layers.size(), 2u);
    EXPECT_EQ(sets.layers[0].settings.lineset, "A");
    EXPECT_EQ(sets.layers[1].settings.lineset, "B");
    const double a = total_length(sets.layers[0]), b = total_length(sets.layers[1]);
    ASSERT_GT(a, 100.0);
    ASSERT_GT(b, 100.0);
    // The two sets split the drawing: nothing lost, nothing doubled (B still hides part of A).
    // Within 1 %: the cuts where B's outline crosses A's creases are searched per layer (measured
    // 0.57 %), while a set's missing or doubled edges would be tens of percent.
    EXPECT_NEAR(a + b, total_length(all.layers[0]), 1e-2 * total_length(all.layers[0]));
    const LineDrawing a_alone = [&] {
        Mesh only_a = two_parts();
        only_a.triangles.resize(12);
        only_a.face_materials.resize(12);
        only_a.face_objects.resize(12);
        only_a.face_marks.resize(12);
        LineExtractor e(only_a);
        return e.draw(camera, 400, 300, {crease_of("", {})});
    }();
    EXPECT_GT(total_length(a_alone.layers[0]), a + 20.0) << "B must hide some of A's lines";
    // B's marked top: its four edges, each with a selected face.
    const LineDrawing top = extractor.draw(camera, 400, 300, {crease_of("top", {.face_mark = -1})});
    EXPECT_GT(total_length(top.layers[0]), 10.0);
    EXPECT_LT(total_length(top.layers[0]), b);
}

}  // namespace
}  // namespace inkshade
