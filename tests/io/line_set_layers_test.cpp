// A drawing's line sets in its outputs: an SVG layer group per set holding its type layers, and
// each layer's set in the lines JSON (docs/lines.md).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "inkshade/line_drawing.hpp"

namespace inkshade {
namespace {

LineLayer layer(const std::string& type, const std::string& set, float x) {
    LineLayer l;
    l.settings = {type, {}, set, {}};
    LinePath p;
    p.points = {{x, 1.0f}, {x, 9.0f}};
    p.depth = {0.5f, 0.5f};
    p.strength = {1.0f, 1.0f};
    l.visible.push_back(p);
    return l;
}

LineDrawing three_sets() {
    LineDrawing d;
    d.width = d.height = 10;
    d.layers = {layer("contour", "", 1.0f), layer("contour", "bolts", 2.0f), layer("crease", "bolts", 3.0f),
                layer("contour", "body", 4.0f)};
    return d;
}

TEST(LineSetLayers, SvgNestsEachSetsLayersInItsOwnGroup) {
    const std::string svg = format_svg(three_sets(), glm::vec4(0.0f));
    const size_t plain = svg.find("<g id=\"contour\"");
    const size_t bolts = svg.find("<g id=\"lineset-bolts\" inkscape:groupmode=\"layer\" inkscape:label=\"bolts\">");
    const size_t bolts_contour = svg.find("<g id=\"bolts-contour\"");
    const size_t bolts_crease = svg.find("<g id=\"bolts-crease\"");
    const size_t body = svg.find("<g id=\"lineset-body\"");
    const size_t body_contour = svg.find("<g id=\"body-contour\"");
    ASSERT_NE(plain, std::string::npos);
    ASSERT_NE(bolts, std::string::npos);
    ASSERT_NE(body, std::string::npos);
    EXPECT_LT(plain, bolts);
    EXPECT_LT(bolts, bolts_contour);
    EXPECT_LT(bolts_contour, bolts_crease);
    EXPECT_LT(bolts_crease, body);
    EXPECT_LT(body, body_contour);
    // The set's group closes after its last layer: two </g> in a row before the next set.
    const std::string between = svg.substr(bolts_crease, body - bolts_crease);
    EXPECT_NE(between.find("</g>\n</g>\n"), std::string::npos);
    size_t opened = 0, closed = 0;
    for (size_t i = svg.find("<g "); i != std::string::npos; i = svg.find("<g ", i + 1)) ++opened;
    for (size_t i = svg.find("</g>"); i != std::string::npos; i = svg.find("</g>", i + 1)) ++closed;
    EXPECT_EQ(opened, closed);
    EXPECT_EQ(opened, 6u);  // four type layers, two sets
}

TEST(LineSetLayers, LinesJsonNamesEachLayersSet) {
    const nlohmann::json j = nlohmann::json::parse(format_lines_json(three_sets()));
    ASSERT_EQ(j["layers"].size(), 4u);
    EXPECT_EQ(j["layers"][0]["lineset"], "");
    EXPECT_EQ(j["layers"][1]["lineset"], "bolts");
    EXPECT_EQ(j["layers"][2]["lineset"], "bolts");
    EXPECT_EQ(j["layers"][3]["lineset"], "body");
}

}  // namespace
}  // namespace inkshade
