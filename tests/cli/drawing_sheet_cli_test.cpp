// Drawings on a sheet: --paper sizes the SVG in mm and gives the image its aspect, --scale
// draws to scale (an orthographic view: so many mm of paper per mm of model), and a style
// with line-unit = "mm" (the ISO 128 preset, technical-iso128) has its widths and dashes in
// mm of paper. Checked on a box whose size is known; bad sheets and scales are one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/run_cli.hpp"

namespace inkshade::test {
namespace {

// A closed box of 100 x 60 x 40 mm (x, y, z) around the origin, faces outward.
std::string write_box(const TempDir& dir) {
    const std::string path = dir.file("box.obj");
    std::ofstream out(path);
    for (int i = 0; i < 8; ++i)
        out << "v " << (i & 1 ? 50 : -50) << ' ' << (i & 2 ? 30 : -30) << ' ' << (i & 4 ? 20 : -20) << '\n';
    // Quads by corner bits (x = 1, y = 2, z = 4), counter-clockwise seen from outside.
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads)
        out << "f " << q[0] + 1 << ' ' << q[1] + 1 << ' ' << q[2] + 1 << '\n'
            << "f " << q[0] + 1 << ' ' << q[2] + 1 << ' ' << q[3] + 1 << '\n';
    return path;
}

// The stroke-width and dash attributes of the SVG layer `id`.
std::string layer_attribute(const std::string& svg, const std::string& id, const std::string& attribute) {
    const size_t at = svg.find("<g id=\"" + id + "\"");
    if (at == std::string::npos) return "(no layer " + id + ")";
    const std::string tag = svg.substr(at, svg.find('>', at) - at);
    std::smatch m;
    if (!std::regex_search(tag, m, std::regex(attribute + "=\"([^\"]*)\""))) return "(no " + attribute + ")";
    return m[1];
}

// Front view of the box on A4 landscape at 1:2 with 10 px per mm of paper: the box's 100 x 60
// mm outline is 50 x 30 mm of paper, 500 x 300 px, and the visible lines are 0.5 mm = 5 px.
TEST(DrawingSheet, BoxDrawnToScaleOnA4) {
    TempDir dir;
    const std::string box = write_box(dir);
    auto r = run_cli("lines " + box + " --style technical-iso128 --paper A4 --scale 1:2 --azimuth 0 --elevation 0 " +
                     "--size 2970x2970 -o " + dir.file("b.svg") + " --lines-json " + dir.file("b.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir.file("b.svg"));
    EXPECT_NE(svg.find("width=\"297mm\" height=\"210mm\" viewBox=\"0 0 2970 2100\""), std::string::npos)
        << svg.substr(0, 400);
    EXPECT_EQ(layer_attribute(svg, "crease", "stroke-width"), "5");
    const auto json = nlohmann::json::parse(slurp(dir.file("b.json")));
    EXPECT_EQ(json["width"], 2970);
    EXPECT_EQ(json["height"], 2100);
    float lo_x = std::numeric_limits<float>::max(), hi_x = -lo_x, lo_y = lo_x, hi_y = -lo_x;
    for (const auto& layer : json["layers"])
        for (const auto& path : layer["paths"]) {
            if (path["hidden"]) continue;
            for (const auto& p : path["points"]) {
                lo_x = std::min(lo_x, p[0].get<float>()), hi_x = std::max(hi_x, p[0].get<float>());
                lo_y = std::min(lo_y, p[1].get<float>()), hi_y = std::max(hi_y, p[1].get<float>());
            }
        }
    EXPECT_NEAR(hi_x - lo_x, 500.0f, 1.0f);
    EXPECT_NEAR(hi_y - lo_y, 300.0f, 1.0f);
    EXPECT_NEAR(0.5f * (lo_x + hi_x), 1485.0f, 1.0f) << "the view is centred on the model";
    EXPECT_NEAR(0.5f * (lo_y + hi_y), 1050.0f, 1.0f);
}

// From a corner the box's three back edges are hidden: ISO 128's dashed narrow line, 0.25 mm
// with dashes of 3 mm and gaps of 0.75 mm; a section plane's outline is 0.7 mm.
TEST(DrawingSheet, Iso128HiddenAndSectionLines) {
    TempDir dir;
    const std::string box = write_box(dir);
    auto r = run_cli("lines " + box + " --style technical-iso128 --paper A3-portrait --scale 2:1 --azimuth 30 " +
                     "--elevation 25 --size 2970x2970 --section-plane 0,0,0,1,0,0 -o " + dir.file("b.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir.file("b.svg"));
    // A3 portrait, 297 x 420 mm: the longer side takes the 2970 px, 7.0714 px per mm.
    EXPECT_NE(svg.find("width=\"297mm\" height=\"420mm\" viewBox=\"0 0 2100 2970\""), std::string::npos)
        << svg.substr(0, 400);
    const double px = 2970.0 / 420.0;
    auto near = [&](const std::string& text, double mm) {
        return std::abs(std::stod(text) - mm * px) < 0.01 ? "ok" : text + " is not " + std::to_string(mm * px);
    };
    EXPECT_STREQ(near(layer_attribute(svg, "crease", "stroke-width"), 0.5).c_str(), "ok");
    EXPECT_STREQ(near(layer_attribute(svg, "clip-boundary", "stroke-width"), 0.7).c_str(), "ok");
    const std::string dash = layer_attribute(svg, "crease-hidden-1", "stroke-dasharray");
    const size_t space = dash.find(' ');
    ASSERT_NE(space, std::string::npos) << dash;
    EXPECT_STREQ(near(dash.substr(0, space), 3.0).c_str(), "ok");
    EXPECT_STREQ(near(dash.substr(space + 1), 0.75).c_str(), "ok");
    // level-width halves the hidden level's width: paths carry it as their own stroke-width.
    const size_t hidden = svg.find("<g id=\"crease-hidden-1\"");
    const std::string hidden_layer = svg.substr(hidden, svg.find("</g>", hidden) - hidden);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(hidden_layer, m, std::regex("<path[^>]*stroke-width=\"([^\"]*)\""))) << hidden_layer;
    EXPECT_STREQ(near(m[1], 0.25).c_str(), "ok");
}

// Without a sheet, a line width in mm is in CSS pixels: 96 per inch.
TEST(DrawingSheet, MillimetresWithoutASheetAreCssPixels) {
    TempDir dir;
    {
        std::ofstream(dir.file("mm.toml"))
            << "line-unit = \"mm\"\n[shading]\nmodel = \"flat\"\n[[lines]]\ntype = \"crease\"\nwidth = 1.0\n";
        std::ofstream(dir.file("cm.toml")) << "line-unit = \"cm\"\n[shading]\nmodel = \"flat\"\n";
    }
    auto r = run_cli("lines " + write_box(dir) + " --style " + dir.file("mm.toml") + " -o " + dir.file("c.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir.file("c.svg"));
    EXPECT_NE(svg.find("width=\"1024\" height=\"1024\""), std::string::npos);
    EXPECT_NEAR(std::stod(layer_attribute(svg, "crease", "stroke-width")), 96.0 / 25.4, 1e-3);
    r = run_cli("lines builtin:sphere --style " + dir.file("cm.toml") + " -o " + dir.file("c2.svg"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("line-unit: expected \"px\" or \"mm\""), std::string::npos) << r.err;
}

TEST(DrawingSheet, BadSheetsAndScalesAreOneLineErrors) {
    TempDir dir;
    const std::pair<const char*, const char*> cases[] = {
        {"--scale 1:2", "--scale: a drawing's scale needs its sheet: give --paper too"},
        {"--paper B4", "--paper: expected A0..A5"},
        {"--paper A4-sideways", "--paper: expected A0..A5"},
        {"--paper 0x100", "--paper: expected A0..A5"},
        {"--paper 100x1e9", "--paper: expected A0..A5"},
        {"--paper A4 --scale 1:0", "--scale: expected PAPER:MODEL"},
        {"--paper A4 --scale 2", "--scale: expected PAPER:MODEL"},
        {"--paper A4 --scale -1:2", "--scale: expected PAPER:MODEL"},
        {"--paper A4 --scale 1:2 --ortho-height 3", "--scale and --ortho-height are alternatives"},
        {"--paper A4 --scale 1:2 --distance 3", "--scale and --distance are alternatives"}};
    for (const auto& [options, message] : cases) {
        const auto r = run_cli(std::string("lines builtin:sphere ") + options + " -o " + dir.file("x.svg"));
        EXPECT_EQ(r.status, 2) << options;
        EXPECT_NE(r.err.find(message), std::string::npos) << options << ": " << r.err;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("x.svg"))) << options;
    }
}

}  // namespace
}  // namespace inkshade::test
