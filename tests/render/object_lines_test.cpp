// What the renderer asks of the object-space line drawing (render/frame.hpp object_lines_of).
#include <gtest/gtest.h>

#include "inkshade/lines.hpp"
#include "render/frame.hpp"

namespace inkshade::render {
namespace {

float number(const LineSettings& l, const std::string& name) { return line_param(l, name).at(0); }

TEST(ObjectLines, StrokesAskForVisiblePartsOnly) {
    // technical's convention (dash level 1 in SVG) and `hidden`: the strokes draw level 0 only,
    // so the renderer counts no level past it; other settings pass through unchanged.
    LineSettings contour{.type = "contour", .params = {{"max-level", {1.0f}}, {"width", {3.0f}}}};
    LineSettings crease{.type = "crease", .params = {{"hidden", {1.0f}}, {"angle", {45.0f}}}};
    LineSettings border{.type = "border", .params = {{"min-level", {1.0f}}, {"max-level", {2.0f}}}};
    LineSettings hull{.type = "hull", .params = {}};
    const std::vector<LineSettings> out = object_lines_of({contour, hull, crease, border}, false);
    ASSERT_EQ(out.size(), 3u);  // the hull is image-space
    EXPECT_EQ(out[0].type, "contour");
    EXPECT_EQ(number(out[0], "max-level"), 0.0f);
    EXPECT_EQ(number(out[0], "width"), 3.0f);
    EXPECT_EQ(out[1].type, "crease");
    EXPECT_EQ(number(out[1], "hidden"), 0.0f);
    EXPECT_EQ(number(out[1], "max-level"), 0.0f);
    EXPECT_EQ(number(out[1], "angle"), 45.0f);
    // A layer of hidden levels only is left as asked (its strokes draw nothing either way).
    EXPECT_EQ(number(out[2], "min-level"), 1.0f);
    EXPECT_EQ(number(out[2], "max-level"), 2.0f);
}

}  // namespace
}  // namespace inkshade::render
