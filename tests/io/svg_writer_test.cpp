// format_svg / write_svg / format_lines_json: well-formed XML that rsvg-convert reads, layers
// named for Inkscape, viewBox = image size, stroke attributes, strength runs; JSON round trip.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <vector>

#include <nlohmann/json.hpp>

#include "inkshade/error.hpp"
#include "inkshade/image.hpp"
#include "inkshade/line_drawing.hpp"
#include "support/temp_dir.hpp"

namespace inkshade {
namespace {

struct Element {
    std::string name;
    std::map<std::string, std::string> attributes;
};

// A small XML well-formedness check (no DTD, no entities beyond the five predefined): every
// tag closed in order, attributes quoted and unique, one root. Returns the start tags in
// document order; fails the test on the first problem.
std::vector<Element> parse_xml(const std::string& text) {
    std::vector<Element> elements;
    std::vector<std::string> open;
    size_t i = 0, roots = 0;
    const std::regex attribute(R"re(\s*([A-Za-z_:][-A-Za-z0-9_:.]*)\s*=\s*"([^"<]*)")re");
    while ((i = text.find('<', i)) != std::string::npos) {
        if (text.compare(i, 5, "<?xml") == 0) {
            i = text.find("?>", i);
            EXPECT_NE(i, std::string::npos);
            continue;
        }
        const size_t end = text.find('>', i);
        if (end == std::string::npos) {
            ADD_FAILURE() << "unterminated tag at " << i;
            return elements;
        }
        std::string tag = text.substr(i + 1, end - i - 1);
        i = end + 1;
        if (tag.starts_with("/")) {
            if (open.empty() || open.back() != tag.substr(1)) {
                ADD_FAILURE() << "mismatched </" << tag.substr(1) << ">";
                return elements;
            }
            open.pop_back();
            continue;
        }
        const bool self_closing = tag.ends_with("/");
        if (self_closing) tag.pop_back();
        Element e;
        const size_t name_end = std::min(tag.find_first_of(" \t\n"), tag.size());
        e.name = tag.substr(0, name_end);
        std::string rest = tag.substr(name_end);
        std::smatch m;
        while (std::regex_search(rest, m, attribute) && m.position(0) == 0) {
            EXPECT_TRUE(e.attributes.emplace(m[1].str(), m[2].str()).second) << "duplicate " << m[1];
            rest = m.suffix();
        }
        EXPECT_TRUE(std::all_of(rest.begin(), rest.end(), ::isspace)) << "bad attributes in <" << tag << ">";
        if (open.empty()) ++roots;
        if (!self_closing) open.push_back(e.name);
        elements.push_back(std::move(e));
    }
    EXPECT_TRUE(open.empty()) << "unclosed <" << (open.empty() ? "" : open.back()) << ">";
    EXPECT_EQ(roots, 1u);
    return elements;
}

LinePath path(std::vector<glm::vec2> points, bool closed, std::vector<float> strength = {}) {
    LinePath p;
    p.points = std::move(points);
    p.closed = closed;
    p.depth.assign(p.points.size(), 0.5f);
    p.strength = strength.empty() ? std::vector<float>(p.points.size(), 1.0f) : std::move(strength);
    return p;
}

LineDrawing sample_drawing() {
    LineDrawing d;
    d.width = 200;
    d.height = 100;
    LineLayer contour;
    contour.settings = {"contour", {{"color", {1.0f, 0.5f, 0.0f}}, {"width", {2.5f}}, {"hidden", {1.0f}}}};
    contour.visible.push_back(path({{10, 10}, {190, 10}, {190, 90}, {10, 90}}, true));
    contour.hidden.push_back(path({{20.004f, 50}, {180.333f, 50.5f}}, false));
    contour.hidden.back().level = 1;
    contour.hidden.push_back(path({{20, 60}, {180, 60}}, false));  // behind two surfaces
    contour.hidden.back().level = 2;
    LineLayer suggestive;
    suggestive.settings = {"suggestive", {{"opacity", {0.8f}}}};
    // Fades in: strength 0 → 1 along the path.
    suggestive.visible.push_back(
        path({{0, 0}, {10, 0}, {20, 0}, {30, 0}, {40, 0}}, false, {0.0f, 0.25f, 0.5f, 1.0f, 1.0f}));
    LineLayer crease;
    crease.settings = {"crease", {{"taper", {1.0f}}, {"width", {2.0f}}}};
    crease.visible.push_back(path({{0, 50}, {50, 50}, {100, 50}}, false, {1.0f, 0.5f, 0.5f}));
    d.layers = {contour, suggestive, crease};
    return d;
}

TEST(SvgWriter, WellFormedWithInkscapeLayersAndViewBox) {
    const std::string svg = format_svg(sample_drawing(), glm::vec4(1.0f));
    const std::vector<Element> elements = parse_xml(svg);
    ASSERT_FALSE(elements.empty());
    const Element& root = elements[0];
    EXPECT_EQ(root.name, "svg");
    EXPECT_EQ(root.attributes.at("xmlns"), "http://www.w3.org/2000/svg");
    EXPECT_EQ(root.attributes.at("xmlns:inkscape"), "http://www.inkscape.org/namespaces/inkscape");
    EXPECT_EQ(root.attributes.at("viewBox"), "0 0 200 100");
    EXPECT_EQ(root.attributes.at("width"), "200");
    EXPECT_EQ(root.attributes.at("height"), "100");

    std::vector<std::string> layers;
    for (const Element& e : elements)
        if (e.name == "g") {
            EXPECT_EQ(e.attributes.at("inkscape:groupmode"), "layer");
            EXPECT_EQ(e.attributes.at("inkscape:label"), e.attributes.at("id"));
            EXPECT_EQ(e.attributes.at("fill"), "none");
            EXPECT_EQ(e.attributes.at("stroke-linecap"), "round");
            EXPECT_EQ(e.attributes.at("stroke-linejoin"), "round");
            EXPECT_TRUE(e.attributes.count("stroke-width"));
            layers.push_back(e.attributes.at("id"));
        }
    // Each hidden level its own layer below its visible one, the deepest lowest.
    EXPECT_EQ(layers,
              (std::vector<std::string>{"contour-hidden-2", "contour-hidden-1", "contour", "suggestive", "crease"}));
    int dashed = 0;
    for (const Element& e : elements) {
        if (e.name == "g" && e.attributes.at("id") == "contour") {
            EXPECT_EQ(e.attributes.at("stroke"), "#ff8000");
            EXPECT_EQ(e.attributes.at("stroke-width"), "2.5");
            EXPECT_FALSE(e.attributes.count("stroke-dasharray"));
        }
        if (e.name == "g" && e.attributes.at("id").rfind("contour-hidden-", 0) == 0) {
            EXPECT_TRUE(e.attributes.count("stroke-dasharray"));
            ++dashed;
        }
    }
    EXPECT_EQ(dashed, 2);
    EXPECT_NE(svg.find("<rect id=\"background\""), std::string::npos);
    // Compact numbers, closed loops with Z.
    EXPECT_NE(svg.find("d=\"M10 10 L190 10 190 90 10 90 Z\""), std::string::npos) << svg;
    EXPECT_NE(svg.find("d=\"M20 50 L180.33 50.5\""), std::string::npos) << svg;
}

TEST(SvgWriter, StrengthRunsScaleOpacityOrWidth) {
    const std::string svg = format_svg(sample_drawing(), glm::vec4(0.0f));
    EXPECT_EQ(svg.find("<rect"), std::string::npos) << "alpha 0: no background";
    const std::vector<Element> elements = parse_xml(svg);
    std::vector<Element> suggestive, crease;
    std::string layer;
    // Paths follow their layer's <g> in document order.
    for (const Element& e : elements) {
        if (e.name == "g") layer = e.attributes.at("id");
        if (e.name == "path" && layer == "suggestive") suggestive.push_back(e);
        if (e.name == "path" && layer == "crease") crease.push_back(e);
    }
    // Segment strengths 0.125, 0.375, 0.75, 1 (eighths 1, 3, 6, 8): four runs, opacity scaled.
    ASSERT_EQ(suggestive.size(), 4u);
    EXPECT_EQ(suggestive[0].attributes.at("stroke-opacity"), "0.1");  // 0.8 × 1/8
    EXPECT_EQ(suggestive[0].attributes.at("d"), "M0 0 L10 0");
    EXPECT_EQ(suggestive[2].attributes.at("stroke-opacity"), "0.6");  // 0.8 × 6/8
    EXPECT_FALSE(suggestive[3].attributes.count("stroke-opacity"));   // full strength: the layer's
    // Runs share end points: no gap.
    EXPECT_EQ(suggestive[1].attributes.at("d"), "M10 0 L20 0");
    // Taper: width instead of opacity.
    ASSERT_EQ(crease.size(), 2u);
    EXPECT_EQ(crease[0].attributes.at("stroke-width"), "1.5");  // 2 × 6/8 (segment mean 0.75)
    EXPECT_EQ(crease[1].attributes.at("stroke-width"), "1");    // 2 × 4/8
    EXPECT_FALSE(crease[0].attributes.count("stroke-opacity"));
}

TEST(SvgWriter, RsvgConvertRasterisesIt) {
    test::TempDir dir;
    const std::string svg = dir.file("lines.svg"), png = dir.file("lines.png");
    write_svg(svg, sample_drawing(), glm::vec4(1.0f));
    const int status = std::system(("rsvg-convert " + svg + " -o " + png + " 2>" + dir.file("err")).c_str());
    ASSERT_EQ(status, 0) << "rsvg-convert (librsvg2-bin, installed by scripts/setup) failed";
    // The picture the SVG describes: its size, the orange contour rectangle (2.5 px) where it
    // runs, its dashed hidden line (orange, lighter) and white away from every line.
    const Image img = read_png(png);
    ASSERT_EQ(img.width, 200);
    ASSERT_EQ(img.height, 100);
    for (glm::ivec2 p : {glm::ivec2(100, 10), glm::ivec2(190, 40), glm::ivec2(60, 90), glm::ivec2(10, 70)}) {
        const uint8_t* c = img.pixel(p.x, p.y - (p.y == 10 || p.y == 90 ? 1 : 0));
        EXPECT_GT(int(c[0]), 200) << p.x << "," << p.y;  // orange (1, 0.5, 0) over white
        EXPECT_LT(int(c[2]), 60) << p.x << "," << p.y;
    }
    int dashed_on = 0, dashed_off = 0;
    for (int x = 110; x < 170; ++x) {  // right of the crease, which also runs along y = 50
        const uint8_t* c = img.pixel(x, 50);
        (c[2] < 200 ? dashed_on : dashed_off)++;
    }
    EXPECT_GT(dashed_on, 20) << "the hidden layer is drawn";
    EXPECT_GT(dashed_off, 5) << "and dashed";
    for (glm::ivec2 p : {glm::ivec2(100, 30), glm::ivec2(150, 75), glm::ivec2(195, 97)})
        for (int k = 0; k < 3; ++k) EXPECT_EQ(int(img.pixel(p.x, p.y)[k]), 255) << p.x << "," << p.y;
}

TEST(SvgWriter, WriteFailsCleanlyInMissingDirectory) {
    test::TempDir dir;
    EXPECT_THROW(write_svg(dir.file("no/such/dir/x.svg"), sample_drawing(), glm::vec4(1.0f)), RuntimeError);
}

TEST(LinesJson, RoundTripsLayersAndPaths) {
    const LineDrawing d = sample_drawing();
    const nlohmann::json j = nlohmann::json::parse(format_lines_json(d));
    EXPECT_EQ(j.at("width"), 200);
    EXPECT_EQ(j.at("height"), 100);
    ASSERT_EQ(j.at("layers").size(), 3u);
    const auto& contour = j.at("layers")[0];
    EXPECT_EQ(contour.at("type"), "contour");
    EXPECT_EQ(contour.at("params").at("width"), 2.5);
    EXPECT_EQ(contour.at("params").at("hidden"), true);
    EXPECT_EQ(contour.at("params").at("smooth"), 0);
    EXPECT_EQ(contour.at("stroke").at("color"), nlohmann::json::parse("[1, 0.5, 0]"));
    ASSERT_EQ(contour.at("paths").size(), 3u);
    const auto& loop = contour.at("paths")[0];
    EXPECT_EQ(loop.at("closed"), true);
    EXPECT_EQ(loop.at("hidden"), false);
    ASSERT_EQ(loop.at("points").size(), 4u);
    EXPECT_EQ(loop.at("points")[1], nlohmann::json::parse("[190, 10]"));
    EXPECT_EQ(loop.at("depth")[0], 0.5);
    const auto& hidden = contour.at("paths")[1];
    EXPECT_EQ(hidden.at("hidden"), true);
    EXPECT_EQ(hidden.at("level"), 1);
    EXPECT_EQ(loop.at("level"), 0);
    EXPECT_EQ(contour.at("paths")[2].at("level"), 2);
    EXPECT_NEAR(hidden.at("points")[0][0].get<double>(), 20.004, 1e-9);
    const auto& fade = j.at("layers")[1].at("paths")[0].at("strength");
    EXPECT_EQ(fade, nlohmann::json::parse("[0, 0.25, 0.5, 1, 1]"));
    // Defaults are filled in for parameters the settings do not give.
    EXPECT_EQ(j.at("layers")[1].at("params").at("threshold"), 0.01);
}

}  // namespace
}  // namespace inkshade
