// [[lineset]] tables in style files (docs/styles.md, "Line sets"): selection, defaults, order,
// round trip and the errors.
#include <gtest/gtest.h>

#include "inkshade/error.hpp"
#include "inkshade/style.hpp"
#include "styles/style_error.hpp"

namespace inkshade {
namespace {

const char* kHeader = "[shading]\nmodel = \"lambert\"\n";

using test::style_error;

const char* kTwoSets = R"(
[[lines]]
type = "hull"

[[lineset]]
name = "bolts"
objects = ["Bolt*", "Nut"]
face-mark = true
order = 2
width = 3.0
color = "#ff0000"
max-level = 2
[[lineset.lines]]
type = "contour"
[[lineset.lines]]
type = "crease"
width = 1.0

[[lineset]]
name = "body"
materials = "paint"
invert = true
order = 1
[[lineset.lines]]
type = "contour"
)";

TEST(LineSetStyle, SetsAreFlattenedInOrderWithTheirSelectionAndDefaults) {
    const Style s = parse_style(std::string(kHeader) + kTwoSets, "sets.toml");
    ASSERT_EQ(s.lines.size(), 4u);
    // The style's own [[lines]] first, then the sets by order.
    EXPECT_EQ(s.lines[0].type, "hull");
    EXPECT_EQ(s.lines[0].lineset, "");
    EXPECT_TRUE(s.lines[0].faces.everything());
    EXPECT_EQ(s.lines[1].lineset, "body");
    EXPECT_EQ(s.lines[1].faces.materials, std::vector<std::string>{"paint"});
    EXPECT_TRUE(s.lines[1].faces.invert);
    EXPECT_EQ(s.lines[2].lineset, "bolts");
    EXPECT_EQ(s.lines[2].type, "contour");
    EXPECT_EQ(s.lines[2].faces.objects, (std::vector<std::string>{"Bolt*", "Nut"}));
    EXPECT_EQ(s.lines[2].faces.face_mark, -1);
    // The set's stroke and levels reach its lines unless a line sets its own.
    EXPECT_EQ(stroke_of(s.lines[2]).width, 3.0f);
    EXPECT_EQ(stroke_of(s.lines[2]).color, glm::vec3(1, 0, 0));
    EXPECT_EQ(line_param(s.lines[2], "max-level").at(0), 2.0f);
    EXPECT_EQ(s.lines[3].type, "crease");
    EXPECT_EQ(stroke_of(s.lines[3]).width, 1.0f);
    EXPECT_EQ(stroke_of(s.lines[3]).color, glm::vec3(1, 0, 0));
    EXPECT_EQ(line_set_names(s.lines), (std::vector<std::string>{"", "body", "bolts"}));
}

TEST(LineSetStyle, RoundTripsThroughItsFile) {
    const Style s = parse_style(std::string(kHeader) + kTwoSets, "sets.toml");
    const Style back = parse_style(format_style(s), "sets.toml");  // the same name: format_style writes it
    ASSERT_EQ(back.lines.size(), s.lines.size());
    for (size_t i = 0; i < s.lines.size(); ++i) {
        EXPECT_EQ(back.lines[i].type, s.lines[i].type);
        EXPECT_EQ(back.lines[i].lineset, s.lines[i].lineset);
        EXPECT_EQ(back.lines[i].faces, s.lines[i].faces);
        EXPECT_EQ(stroke_of(back.lines[i]).width, stroke_of(s.lines[i]).width);
    }
    EXPECT_EQ(format_style(back), format_style(s));
}

TEST(LineSetStyle, OverridesReachTheTypeInEverySet) {
    Style s = parse_style(std::string(kHeader) + kTwoSets, "sets.toml");
    apply_override(s, "contour.width=5");
    EXPECT_EQ(stroke_of(s.lines[1]).width, 5.0f);
    EXPECT_EQ(stroke_of(s.lines[2]).width, 5.0f);
}

TEST(LineSetStyle, BadSetsAreOneLineErrors) {
    const std::string h = kHeader;
    const std::string contour = "[[lineset.lines]]\ntype = \"contour\"\n";
    EXPECT_NE(style_error(h + "[[lineset]]\n" + contour).find("needs name"), std::string::npos);
    EXPECT_NE(style_error(h + "[[lineset]]\nname = \"a b\"\n" + contour).find("lineset name 'a b'"), std::string::npos);
    EXPECT_NE(style_error(h + "[[lineset]]\nname = \"a\"\n").find("needs [[lineset.lines]]"), std::string::npos);
    EXPECT_NE(style_error(h + "[[lineset]]\nname = \"a\"\n" + contour + "[[lineset]]\nname = \"a\"\n" + contour)
                  .find("used twice"),
              std::string::npos);
    EXPECT_NE(style_error(h + "[[lineset]]\nname = \"a\"\nfoo = 1\n" + contour).find("unknown key 'foo'"),
              std::string::npos);
    EXPECT_NE(style_error(h + "[[lineset]]\nname = \"a\"\nface-mark = 300\n" + contour).find("face-mark"),
              std::string::npos);
    EXPECT_NE(style_error(h + "[[lineset]]\nname = \"a\"\nmaterials = []\n" + contour).find("empty list"),
              std::string::npos);
    EXPECT_NE(style_error(h + "[[lineset]]\nname = \"a\"\n" + contour + contour).find("listed twice"),
              std::string::npos);
    // Image-space lines are found per pixel: no face selection, and one setting in the style.
    EXPECT_NE(style_error(h + "[[lineset]]\nname = \"a\"\nobjects = \"x\"\n[[lineset.lines]]\ntype = \"hull\"\n")
                  .find("image-space line type 'hull'"),
              std::string::npos);
    EXPECT_NE(style_error(h + "[[lines]]\ntype = \"hull\"\n[[lineset]]\nname = \"a\"\n[[lineset.lines]]\ntype = "
                              "\"hull\"\n")
                  .find("drawn twice"),
              std::string::npos);
    EXPECT_EQ(style_error(h + "[[lineset]]\nname = \"a\"\n[[lineset.lines]]\ntype = \"hull\"\n"), "");
}

}  // namespace
}  // namespace inkshade
