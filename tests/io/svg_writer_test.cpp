// format_svg / write_svg / format_lines_json: well-formed XML that rsvg-convert reads, layers
// named for Inkscape, viewBox = image size, stroke attributes, strength runs; JSON round trip.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <vector>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include "geometry/builtin_models.hpp"
#include "geometry/stroke_paths.hpp"
#include "geometry/stroke_style.hpp"
#include "inkshade/error.hpp"
#include "inkshade/image.hpp"
#include "inkshade/line_drawing.hpp"
#include "io/svg_path_data.hpp"
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
        // Attributes NAME="VALUE" scanned by hand: std::regex recurses once per character and
        // overflows the stack on a long path's `d` (under AddressSanitizer's larger frames).
        size_t at = name_end;
        auto skip_space = [&] {
            while (at < tag.size() && std::isspace(static_cast<unsigned char>(tag[at]))) ++at;
        };
        auto name_char = [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '-' || c == '.';
        };
        for (skip_space(); at < tag.size(); skip_space()) {
            const size_t name_begin = at;
            if (!(std::isalpha(static_cast<unsigned char>(tag[at])) || tag[at] == '_' || tag[at] == ':')) break;
            while (at < tag.size() && name_char(tag[at])) ++at;
            const std::string name = tag.substr(name_begin, at - name_begin);
            skip_space();
            if (at >= tag.size() || tag[at] != '=') break;
            ++at;
            skip_space();
            if (at >= tag.size() || tag[at] != '"') break;
            const size_t value_end = tag.find('"', at + 1);
            if (value_end == std::string::npos || tag.find('<', at + 1) < value_end) break;
            EXPECT_TRUE(e.attributes.emplace(name, tag.substr(at + 1, value_end - at - 1)).second)
                << "duplicate " << name;
            at = value_end + 1;
        }
        EXPECT_EQ(at, tag.size()) << "bad attributes in <" << tag.substr(0, 200) << ">";
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

// Half the thickness of a horizontal stroke along y = `y` at x, from its outline's path data:
// the largest |y' - y| where the outline crosses the vertical line at x (its pieces sampled
// finely, linear between samples).
double half_width_at(const std::string& outline, double y, double x) {
    double h = 0.0;
    for (const test::SvgSubpath& sub : test::parse_path_data(outline))
        for (const io::CubicBezier& b : sub.pieces) {
            glm::dvec2 prev = b.p0;
            for (int k = 1; k <= 256; ++k) {
                const glm::dvec2 q = b.at(k / 256.0);
                if ((prev.x - x) * (q.x - x) <= 0.0 && prev.x != q.x)
                    h = std::max(h, std::abs(glm::mix(prev.y, q.y, (x - prev.x) / (q.x - prev.x)) - y));
                prev = q;
            }
        }
    return h;
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
    // Taper: the strength sets the width (1, 0.5, 0.5 of 2 px), so the crease is a filled
    // outline, not a stroke: half-widths 1 at x = 0 and 0.5 from x = 50 on.
    ASSERT_EQ(crease.size(), 1u);
    EXPECT_EQ(crease[0].attributes.at("stroke"), "none");
    EXPECT_EQ(crease[0].attributes.at("fill"), "#000000");
    EXPECT_FALSE(crease[0].attributes.count("stroke-width"));
    const std::string outline = crease[0].attributes.at("d");
    EXPECT_NEAR(half_width_at(outline, 50.0, 0.0), 1.0, 0.02);
    EXPECT_NEAR(half_width_at(outline, 50.0, 25.0), 0.75, 0.02);
    EXPECT_NEAR(half_width_at(outline, 50.0, 75.0), 0.5, 0.02);
    EXPECT_NEAR(half_width_at(outline, 50.0, 100.0), 0.5, 0.02);
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

// The paths of layer `id` in document order.
std::vector<Element> layer_paths(const std::vector<Element>& elements, const std::string& id) {
    std::vector<Element> out;
    std::string layer;
    for (const Element& e : elements) {
        if (e.name == "g") layer = e.attributes.at("id");
        if (e.name == "path" && layer == id) out.push_back(e);
    }
    return out;
}

// One layer of `type` with `params`, its paths finished by the layer's stroke modifiers.
LineDrawing styled_drawing(const std::string& type, ParamValues params, std::vector<LinePath> paths, int width = 260,
                           int height = 120) {
    LineDrawing d;
    d.width = width;
    d.height = height;
    LineLayer layer;
    layer.settings = {type, std::move(params)};
    layer.visible = geometry::style_strokes(std::move(paths), geometry::StrokeModifiers::of(layer.settings), {}, 0);
    d.layers.push_back(layer);
    return d;
}

TEST(SvgWriter, TaperedStrokeIsAFilledOutlineWithZeroEndsAndFullMiddle) {
    // 200 px along y = 50, width 4, tapering in over 50 px and out over 50 px.
    const LineDrawing d = styled_drawing("contour", {{"width", {4.0f}}, {"taper-in", {50.0f}}, {"taper-out", {50.0f}}},
                                         {test::straight_path({30, 50}, {230, 50})});
    const std::string svg = format_svg(d, glm::vec4(1.0f));
    const std::vector<Element> paths = layer_paths(parse_xml(svg), "contour");
    ASSERT_EQ(paths.size(), 1u);
    EXPECT_EQ(paths[0].attributes.at("stroke"), "none");
    const std::string outline = paths[0].attributes.at("d");
    const double expected[][2] = {{30, 0}, {42.5, 0.5}, {55, 1}, {80, 2}, {130, 2}, {180, 2}, {205, 1}, {230, 0}};
    for (const auto& [x, h] : expected) EXPECT_NEAR(half_width_at(outline, 50.0, x), h, 0.25) << "x = " << x;
    // Nothing of the outline strays from the stroke.
    for (glm::dvec2 q : test::sample_path_data(outline)) {
        EXPECT_GE(q.x, 30.0 - 0.25);
        EXPECT_LE(q.x, 230.0 + 0.25);
        EXPECT_LE(std::abs(q.y - 50.0), 2.0 + 0.25);
    }

    // rsvg-convert fills it: dark in the middle, nothing left of the start.
    test::TempDir dir;
    write_svg(dir.file("t.svg"), d, glm::vec4(1.0f));
    ASSERT_EQ(std::system(("rsvg-convert " + dir.file("t.svg") + " -o " + dir.file("t.png")).c_str()), 0);
    const Image img = read_png(dir.file("t.png"));
    EXPECT_LT(int(img.pixel(130, 49)[0]), 40);
    EXPECT_LT(int(img.pixel(130, 50)[0]), 40);
    EXPECT_GT(int(img.pixel(130, 52)[0]), 215) << "2 px from the centre line: outside";
    EXPECT_EQ(int(img.pixel(25, 49)[0]), 255);
}

TEST(SvgWriter, ConstantWidthLayersStayStrokedWithTheirCapsAndJoins) {
    const LineDrawing d = styled_drawing("crease", {{"width", {3.0f}}, {"cap", {0.0f}}, {"join", {2.0f}}},
                                         {test::square_path({20, 20}, 60), test::straight_path({10, 100}, {200, 100})});
    const std::vector<Element> elements = parse_xml(format_svg(d, glm::vec4(1.0f)));
    for (const Element& e : elements)
        if (e.name == "g") {
            EXPECT_EQ(e.attributes.at("stroke-linecap"), "butt");
            EXPECT_EQ(e.attributes.at("stroke-linejoin"), "bevel");
            EXPECT_EQ(e.attributes.at("stroke-width"), "3");
        }
    const std::vector<Element> paths = layer_paths(elements, "crease");
    ASSERT_EQ(paths.size(), 2u);
    for (const Element& p : paths) {
        EXPECT_FALSE(p.attributes.count("fill")) << "a stroke, not an outline";
        EXPECT_FALSE(p.attributes.count("stroke-width")) << "the layer's width";
    }
    // Straight sides stay straight lines with exact corners.
    EXPECT_EQ(paths[0].attributes.at("d"), "M20 20 L80 20 80 80 20 80 Z");
    EXPECT_EQ(paths[1].attributes.at("d"), "M10 100 L200 100");
}

TEST(SvgWriter, BezierPathsStayWithinAQuarterPixelInAFractionOfTheText) {
    LineDrawing d;
    d.width = d.height = 400;
    LineLayer layer;
    layer.settings = {"contour", {}};
    const int n = 1257;  // a point every 0.25 rad · px on a circle of radius 150 (about 0.75 px)
    layer.visible.push_back(test::circle_path({200, 200}, 150, n));
    d.layers.push_back(layer);
    const std::string bezier = format_svg(d, glm::vec4(1.0f));
    const std::string polyline = format_svg(d, glm::vec4(1.0f), {.polylines = true});
    const std::vector<Element> paths = layer_paths(parse_xml(bezier), "contour");
    ASSERT_EQ(paths.size(), 1u);
    const std::string data = paths[0].attributes.at("d");
    EXPECT_NE(data.find('C'), std::string::npos);
    EXPECT_EQ(data.back(), 'Z');
    const std::vector<test::SvgSubpath> sub = test::parse_path_data(data);
    ASSERT_EQ(sub.size(), 1u);
    EXPECT_TRUE(sub[0].closed);
    double worst = 0.0;
    for (glm::dvec2 q : test::sample_path_data(data, 64))
        worst = std::max(worst, std::abs(glm::length(q - glm::dvec2(200.0)) - 150.0));
    EXPECT_LE(worst, 0.25);
    const std::vector<Element> poly = layer_paths(parse_xml(polyline), "contour");
    EXPECT_EQ(poly[0].attributes.at("d").find('C'), std::string::npos);
    EXPECT_LT(bezier.size() * 10, polyline.size()) << bezier.size() << " vs " << polyline.size() << " bytes";
}

TEST(SvgWriter, ColourAlongTheStrokeWritesRunsFromColourToEnd) {
    const LineDrawing d = styled_drawing(
        "contour", {{"color", {1.0f, 0.0f, 0.0f}}, {"color-end", {0.0f, 0.0f, 1.0f}}, {"color-along", {2.0f}}},
        {test::straight_path({10, 50}, {250, 50})});
    const std::vector<Element> paths = layer_paths(parse_xml(format_svg(d, glm::vec4(1.0f))), "contour");
    ASSERT_GT(paths.size(), 20u) << "runs of one 8-bit colour each";
    // Each run's colour (the layer's when it has none), red at the start to blue at the end.
    auto rgb = [](const Element& e) {
        const std::string hex = e.attributes.count("stroke") ? e.attributes.at("stroke") : "#ff0000";
        return glm::ivec3(std::stoi(hex.substr(1, 2), nullptr, 16), std::stoi(hex.substr(3, 2), nullptr, 16),
                          std::stoi(hex.substr(5, 2), nullptr, 16));
    };
    EXPECT_GE(rgb(paths.front()).r, 254);
    EXPECT_LE(rgb(paths.front()).b, 1);
    EXPECT_LE(rgb(paths.back()).r, 1);
    EXPECT_GE(rgb(paths.back()).b, 254);
    EXPECT_NEAR(rgb(paths[paths.size() / 2]).r, 128, 3);
    // Runs follow each other without gaps.
    for (size_t k = 1; k < paths.size(); ++k) {
        const auto a = test::parse_path_data(paths[k - 1].attributes.at("d"));
        const auto b = test::parse_path_data(paths[k].attributes.at("d"));
        EXPECT_EQ(a.back().pieces.back().p3, b.front().pieces.front().p0);
    }
}

// Numbers have two decimals, rounded from the exact binary value with ties to even (printf's
// "%.2f"), trailing zeros and a lone "-0" dropped.
TEST(SvgWriter, NumbersRoundToTwoDecimalsAsPrintfDoes) {
    LineDrawing d;
    d.width = d.height = 2000;
    LineLayer layer;
    layer.settings = {"contour", {{"width", {2.5f}}}};
    // 0.125 and 0.625 are ties (to even: .12, .62); 2.675f and 1.005f lie just below .675 and
    // .005; -0.004 rounds to zero, -0.006 does not.
    layer.visible.push_back(
        path({{0.125f, 0.375f}, {2.675f, 1.005f}, {-0.004f, -0.006f}, {0.625f, 0.875f}, {1234.5678f, 10.0f}}, false));
    d.layers.push_back(layer);
    const std::vector<Element> paths =
        layer_paths(parse_xml(format_svg(d, glm::vec4(0.0f), {.polylines = true})), "contour");
    ASSERT_EQ(paths.size(), 1u);
    EXPECT_EQ(paths[0].attributes.at("d"), "M0.12 0.38 L2.67 1 0 -0.01 0.62 0.88 1234.57 10");
}

// Paths are formatted in parallel: the bytes must not depend on the thread count, and the
// paths keep the drawing's order.
TEST(SvgWriter, SameBytesOnOneAndTwoThreadsWithPathsInOrder) {
    LineDrawing d;
    d.width = d.height = 1000;
    LineLayer layer;
    layer.settings = {"contour", {}};
    for (int k = 0; k < 300; ++k) {
        std::vector<glm::vec2> points;
        for (int i = 0; i < 40; ++i)
            points.push_back(
                {float(10 + 3 * k % 900) + 5.0f * float(i), 20.0f + float(k) + 8.0f * std::sin(0.3f * float(i + k))});
        std::vector<float> strength(points.size(), k % 3 == 0 ? 0.5f : 1.0f);
        layer.visible.push_back(path(points, k % 7 == 0, strength));
    }
    d.layers.push_back(layer);
    auto on = [&](size_t threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        return format_svg(d, glm::vec4(1.0f));
    };
    const std::string one = on(1);
    EXPECT_EQ(one, on(2));
    EXPECT_EQ(one, on(4));
    const std::vector<Element> paths = layer_paths(parse_xml(one), "contour");
    ASSERT_EQ(paths.size(), 300u);
    for (size_t k = 0; k < paths.size(); ++k) {
        const std::vector<test::SvgSubpath> sub = test::parse_path_data(paths[k].attributes.at("d"));
        ASSERT_FALSE(sub.empty());
        ASSERT_FALSE(sub[0].pieces.empty());
        EXPECT_NEAR(sub[0].pieces[0].p0.x, layer.visible[k].points[0].x, 0.01) << "path " << k;
        EXPECT_NEAR(sub[0].pieces[0].p0.y, layer.visible[k].points[0].y, 0.01) << "path " << k;
    }
}

// The whole `lines` pipeline of the thirteen object-space types on a teapot (the hatching's
// families on threads of their own, intersections beside curvature, paths formatted in
// parallel) writes the same SVG on one thread and on two.
TEST(SvgWriter, AllObjectSpaceTypesSameBytesOnOneAndTwoThreads) {
    const Mesh teapot = builtin::teapot(16);
    CameraOptions view;
    view.azimuth_degrees = 30.0f;
    view.elevation_degrees = 20.0f;
    const Camera camera = frame_camera(teapot.bounds(), view, 800.0f / 600.0f);
    std::vector<LineSettings> lines;
    for (const char* type : {"contour", "suggestive", "crease", "border", "ridge", "valley", "intersection", "isophote",
                             "topo", "suggestive-highlight", "principal-highlight", "apparent-ridge", "hatch"})
        lines.push_back({type, {}});
    auto on = [&](size_t threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        LineExtractor extractor(teapot);
        return format_svg(extractor.draw(camera, 800, 600, lines), glm::vec4(1.0f));
    };
    const std::string one = on(1);
    const std::vector<Element> elements = parse_xml(one);
    EXPECT_GT(layer_paths(elements, "hatch").size(), 20u);
    EXPECT_FALSE(layer_paths(elements, "intersection").empty());
    EXPECT_FALSE(layer_paths(elements, "contour").empty());
    EXPECT_EQ(one, on(2));
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
