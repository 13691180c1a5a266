// Intersection priority (Line Art): two boxes crossing, the line where they meet belongs to the
// box of higher priority — every segment's `face` is on it — whichever box comes first, and
// only that box's line set draws it.
#include "geometry/intersection_priority.hpp"

#include <gtest/gtest.h>

#include "analytic_meshes.hpp"
#include "geometry/connected_objects.hpp"
#include "geometry/face_selection.hpp"
#include "geometry/intersection_lines.hpp"
#include "geometry/line_types/object_line_registry.hpp"
#include "geometry/visibility.hpp"

namespace inkshade::geometry {
namespace {

// Box A = [-1, 1]³ (faces 0–11), box B = [-0.5, 0.5]³ moved by (1, 0.3, 0.2) (faces 12–23).
Mesh two_boxes() {
    Mesh m = test::cube(1.0f);
    const Mesh b = test::cube(0.5f);
    const uint32_t base = uint32_t(m.positions.size());
    for (const glm::vec3& p : b.positions) m.positions.push_back(p + glm::vec3(1.0f, 0.3f, 0.2f));
    for (const glm::uvec3& t : b.triangles) m.triangles.push_back(t + base);
    return m;
}

// The intersection type's segments for these priorities, through its registration.
std::vector<LineSegment> owned_segments(const Mesh& mesh, std::vector<float> priorities) {
    MeshLineData data(mesh);
    const RayScene scene(data.mesh());
    const Camera camera{};
    const Light light{};
    const std::optional<SectionPlane> section;
    const LineView view{camera, light, section, scene};
    const ObjectLineType* type = object_line_type("intersection");
    EXPECT_NE(type, nullptr);
    return type->extract(data, view, {"intersection", {{"priority", std::move(priorities)}}});
}

TEST(IntersectionPriority, TheLineBelongsToTheHigherPriorityBox) {
    const Mesh mesh = two_boxes();
    const std::vector<uint32_t> objects = object_numbers(face_objects(mesh));
    ASSERT_EQ(objects.size(), 24u);
    for (uint32_t f = 0; f < 24; ++f) EXPECT_EQ(objects[f], f < 12 ? 0u : 1u);
    const size_t count = extract_intersections(mesh).size();
    ASSERT_GT(count, 0u);
    const auto expect_owner = [&](const std::vector<float>& priorities, bool owner_is_b) {
        const std::vector<LineSegment> segments = owned_segments(mesh, priorities);
        ASSERT_EQ(segments.size(), count);
        for (const LineSegment& s : segments) {
            EXPECT_EQ(s.face >= 12, owner_is_b) << "face " << s.face;
            EXPECT_EQ(s.face_b >= 12, !owner_is_b) << "face_b " << s.face_b;
        }
    };
    expect_owner({0.0f, 2.0f}, true);   // B over A
    expect_owner({3.0f, 1.0f}, false);  // A over B
    expect_owner({0.0f}, false);        // a tie: as extracted, the lower face (box A's)
    expect_owner({1.0f}, false);        // B past the list: priority 0
}

TEST(IntersectionPriority, ALineSetTakesTheLinesItsObjectOwns) {
    // Each box selected by a line set: the line where they cross is drawn by both sets on a
    // tie, and by the higher-priority box's set alone when the priorities differ.
    Mesh mesh = two_boxes();
    mesh.object_names = {"A", "B"};
    for (uint32_t f = 0; f < 24; ++f) mesh.face_objects.push_back(f < 12 ? 0u : 1u);
    const SelectedFaces in_a(mesh, {.objects = {"A"}}), in_b(mesh, {.objects = {"B"}});
    const auto kept = [&](const SelectedFaces& set, const std::vector<float>& priorities) {
        std::vector<LineSegment> segments = owned_segments(mesh, priorities);
        set.filter(segments);
        return segments.size();
    };
    const size_t count = extract_intersections(mesh).size();
    EXPECT_EQ(kept(in_a, {0.0f}), count);
    EXPECT_EQ(kept(in_b, {0.0f}), count);
    EXPECT_EQ(kept(in_a, {0.0f, 2.0f}), 0u);
    EXPECT_EQ(kept(in_b, {0.0f, 2.0f}), count);
    EXPECT_EQ(kept(in_a, {3.0f, 1.0f}), count);
    EXPECT_EQ(kept(in_b, {3.0f, 1.0f}), 0u);
}

}  // namespace
}  // namespace inkshade::geometry
