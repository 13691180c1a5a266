// The object-space line types' registrations: each has its extractor, and what it needs of the
// mesh-wide data or of the visibility test is declared there (LineExtractor names no type).
#include "geometry/line_types/object_line_registry.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace inkshade::geometry {
namespace {

TEST(ObjectLineRegistry, EveryObjectSpaceTypeHasAnExtractor) {
    size_t count = 0;
    for (const LineType* type : line_types()) {
        if (type->space != LineSpace::Object) continue;
        const ObjectLineType* object = object_line_type(type->name);
        ASSERT_NE(object, nullptr) << type->name;
        EXPECT_NE(object->extract, nullptr) << type->name;
        EXPECT_TRUE(!object->needs.creases || type->param("angle")) << type->name;
        ++count;
    }
    EXPECT_GE(count, 7u);
    EXPECT_EQ(object_line_type("hull"), nullptr);  // an image-space type
    EXPECT_EQ(object_line_type("scribbles"), nullptr);
}

TEST(ObjectLineRegistry, NeedsAreDeclaredAtRegistration) {
    EXPECT_TRUE(object_line_type("crease")->needs.creases);
    EXPECT_TRUE(object_line_type("border")->needs.adjacency);
    EXPECT_TRUE(object_line_type("intersection")->needs.intersections);
    EXPECT_TRUE(object_line_type("suggestive")->needs.curvature);
    EXPECT_TRUE(object_line_type("contour")->needs.contour_folds);
    EXPECT_FALSE(object_line_type("suggestive")->needs.contour_folds);
}

std::vector<LineSegment> no_segments(MeshLineData&, const LineView&, const LineSettings&) { return {}; }

TEST(ObjectLineRegistry, CreasesWithoutAnAngleAreAProgrammingError) {
    // Refused before anything is registered.
    EXPECT_THROW(
        ObjectLineRegistration({.name = "no-angle-test", .summary = "", .params = {}}, no_segments, {.creases = true}),
        std::logic_error);
    EXPECT_EQ(object_line_type("no-angle-test"), nullptr);
}

}  // namespace
}  // namespace inkshade::geometry
