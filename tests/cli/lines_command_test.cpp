// `inkshade lines`: SVG output that rsvg-convert rasterises onto the same pixels as
// `inkshade render`'s silhouette, --lines-json, --set for line types, one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

// Rasterises an SVG with rsvg-convert (librsvg2-bin, installed by scripts/setup).
Image rasterise(const TempDir& dir, const std::string& svg) {
    const std::string png = svg + ".png";
    const int status = std::system(("rsvg-convert " + svg + " -o " + png + " 2>" + dir.file("rsvg.err")).c_str());
    EXPECT_EQ(status, 0) << slurp(dir.file("rsvg.err"));
    return read_png(png);
}

// Rasterised contour of `inkshade lines` against the silhouette of `inkshade render` with the
// same camera options (an off-centre target, so a flipped or shifted image axis would miss).
void expect_lines_on_silhouette(const std::string& projection) {
    TempDir dir;
    const std::string camera =
        " --size 160x120 --azimuth 30 --elevation 20 --target 0.3,0.35,0 --background transparent " + projection + " ";
    auto r = run_cli("lines builtin:sphere --lines contour" + camera + "-o " + dir.file("s.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli("render builtin:sphere" + camera + "-o " + dir.file("s.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    const Image lines = rasterise(dir, dir.file("s.svg"));
    const Image shaded = read_png(dir.file("s.png"));
    ASSERT_EQ(lines.width, 160);
    ASSERT_EQ(lines.height, 120);
    ASSERT_EQ(shaded.width, 160);

    // Boundary of the rendered sphere: pixels whose coverage (alpha) differs from a 4-neighbour.
    auto inside = [&](int x, int y) { return shaded.pixel(x, y)[3] >= 128; };
    std::vector<uint8_t> boundary(size_t(160 * 120), 0);
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x) {
            if (x + 1 < 160 && inside(x, y) != inside(x + 1, y)) boundary[y * 160 + x] = boundary[y * 160 + x + 1] = 1;
            if (y + 1 < 120 && inside(x, y) != inside(x, y + 1))
                boundary[y * 160 + x] = boundary[(y + 1) * 160 + x] = 1;
        }
    int line_pixels = 0, near = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x) {
            if (lines.pixel(x, y)[3] < 128) continue;
            ++line_pixels;
            bool hit = false;
            for (int dy = -1; dy <= 1 && !hit; ++dy)
                for (int dx = -1; dx <= 1 && !hit; ++dx) {
                    const int u = x + dx, v = y + dy;
                    hit = u >= 0 && v >= 0 && u < 160 && v < 120 && boundary[v * 160 + u];
                }
            near += hit;
        }
    EXPECT_GT(line_pixels, 200) << "the outline ring is drawn";
    EXPECT_GE(near, 0.95 * line_pixels) << near << " of " << line_pixels << " line pixels on the silhouette";
}

TEST(LinesCommand, SphereSvgRasterisesOntoRenderedSilhouette) {
    expect_lines_on_silhouette("");
    expect_lines_on_silhouette("--ortho");
}

TEST(LinesCommand, DefaultLinesJsonAndSets) {
    TempDir dir;
    auto r = run_cli("lines builtin:teapot --size 200x150 --hidden --set contour.width=3 --set crease.angle=45 -o " +
                     dir.file("t.svg") + " --lines-json " + dir.file("t.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << r.err;
    const std::string svg = slurp(dir.file("t.svg"));
    for (const char* id : {"contour", "suggestive", "crease", "border", "contour-hidden-1"})
        EXPECT_NE(svg.find("<g id=\"" + std::string(id) + "\""), std::string::npos) << id;
    EXPECT_NE(svg.find("viewBox=\"0 0 200 150\""), std::string::npos);
    const nlohmann::json j = nlohmann::json::parse(slurp(dir.file("t.json")));
    ASSERT_EQ(j.at("layers").size(), 4u);
    EXPECT_EQ(j.at("layers")[0].at("type"), "contour");
    EXPECT_EQ(j.at("layers")[0].at("stroke").at("width"), 3.0);
    EXPECT_EQ(j.at("layers")[2].at("params").at("angle"), 45.0);
    EXPECT_FALSE(j.at("layers")[0].at("paths").empty());
    bool any_hidden = false;
    for (const auto& p : j.at("layers")[0].at("paths")) {
        any_hidden |= p.at("hidden").get<bool>();
        EXPECT_EQ(p.at("hidden").get<bool>(), p.at("level").get<int>() > 0);
    }
    EXPECT_TRUE(any_hidden) << "the teapot hides part of its own contour (--hidden)";
}

// Suggestive contours keep their short pieces by default, as rtsc 1.6 draws every trimmed piece;
// `min-length = 4` (DeCarlo 2003 §4's filter) drops exactly the pieces under 4 px.
TEST(LinesCommand, SuggestiveContoursKeepShortPiecesUnlessMinLengthIsSet) {
    TempDir dir;
    auto lengths = [&](const std::string& set) {
        const auto r = run_cli("lines builtin:teapot --size 400x300 --lines suggestive " + set + " -o " +
                               dir.file("s.svg") + " --lines-json " + dir.file("s.json"));
        EXPECT_EQ(r.status, 0) << r.err;
        const nlohmann::json layer = nlohmann::json::parse(slurp(dir.file("s.json"))).at("layers").at(0);
        std::vector<double> out;
        for (const auto& path : layer.at("paths")) {
            double length = 0.0;
            const auto& points = path.at("points");
            for (size_t i = 1; i < points.size(); ++i)
                length += std::hypot(points[i][0].get<double>() - points[i - 1][0].get<double>(),
                                     points[i][1].get<double>() - points[i - 1][1].get<double>());
            out.push_back(length);
        }
        return out;
    };
    const std::vector<double> all = lengths(""), filtered = lengths("--set suggestive.min-length=4");
    const auto shorter = [](const std::vector<double>& v) {
        return std::count_if(v.begin(), v.end(), [](double l) { return l < 4.0; });
    };
    EXPECT_GT(shorter(all), 0) << "the teapot has suggestive pieces under 4 px";
    EXPECT_EQ(shorter(filtered), 0);
    EXPECT_EQ(filtered.size(), all.size() - size_t(shorter(all)));
}

// Levels by --occlusion-levels: 0-1 adds the contour behind one surface (dashed layer
// contour-hidden-1) and nothing deeper; 1- leaves the visible layer empty and keeps every hidden
// level; the JSON's levels match the layers.
TEST(LinesCommand, OcclusionLevelsSelectLayers) {
    TempDir dir;
    const std::string base = "lines builtin:torus --up-axis z --elevation 20 --size 240x180 --lines contour ";
    auto r = run_cli(base + "--occlusion-levels 0-1 -o " + dir.file("a.svg") + " --lines-json " + dir.file("a.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    std::string svg = slurp(dir.file("a.svg"));
    EXPECT_NE(svg.find("<g id=\"contour\""), std::string::npos);
    EXPECT_NE(svg.find("<g id=\"contour-hidden-1\""), std::string::npos) << "a torus hides its inner contour";
    EXPECT_EQ(svg.find("<g id=\"contour-hidden-2\""), std::string::npos);
    nlohmann::json j = nlohmann::json::parse(slurp(dir.file("a.json")));
    std::set<int> levels;
    for (const auto& p : j.at("layers")[0].at("paths")) levels.insert(p.at("level").get<int>());
    EXPECT_EQ(levels, (std::set<int>{0, 1}));

    r = run_cli(base + "--occlusion-levels 1- -o " + dir.file("b.svg") + " --lines-json " + dir.file("b.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    j = nlohmann::json::parse(slurp(dir.file("b.json")));
    levels.clear();
    for (const auto& p : j.at("layers")[0].at("paths")) levels.insert(p.at("level").get<int>());
    ASSERT_FALSE(levels.empty());
    EXPECT_GE(*levels.begin(), 1) << "no visible path";
    EXPECT_GE(*levels.rbegin(), 2) << "the inner contour behind the whole tube crosses two surfaces";
}

TEST(LinesCommand, TimingPrintsStagesAndTotal) {
    TempDir dir;
    auto r = run_cli("lines builtin:torus --size 64x64 --timing 3 -o " + dir.file("t.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* stage : {"extract", "visibility", "chain", "total", "svg", "once per mesh"})
        EXPECT_NE(r.out.find(stage), std::string::npos) << r.out;
}

// Issue 34's line kinds by name, with --section-plane for clip-boundary (a plane through the
// torus's centre across its axis: its two equator circles, drawn with their hidden parts); the
// torus has one material, so no material boundary. Bad planes are one-line errors.
TEST(LinesCommand, NewerLineKindsAndSectionPlane) {
    TempDir dir;
    const std::vector<std::string> types = {"light-contour", "clip-boundary", "silhouette", "external-contour",
                                            "material-boundary"};
    auto r = run_cli(
        "lines builtin:torus --size 320x240 --lines "
        "light-contour,clip-boundary,silhouette,external-contour,material-boundary "
        "--section-plane 0,0,0,0,0,1 --set clip-boundary.hidden=1 -o " +
        dir.file("t.svg") + " --lines-json " + dir.file("t.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    const auto json = nlohmann::json::parse(slurp(dir.file("t.json")));
    ASSERT_EQ(json["layers"].size(), types.size());
    for (size_t i = 0; i < types.size(); ++i) {
        EXPECT_EQ(json["layers"][i]["type"], types[i]);
        EXPECT_EQ(json["layers"][i]["paths"].empty(), types[i] == "material-boundary") << types[i];
    }
    for (const char* bad : {"0,0,0,0,0,0", "0,0,0,1,1", "0,0,0,1,x,0"}) {
        r = run_cli(std::string("lines builtin:torus --lines clip-boundary --section-plane ") + bad + " -o " +
                    dir.file("b.svg"));
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_NE(r.err.find("--section-plane: expected X,Y,Z,NX,NY,NZ"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

// An OBJ's `l` lines: `info` counts their segments, `lines --lines loose` draws them (a line
// through a box sticks out on both sides, so some of it is seen from any side).
TEST(LinesCommand, LooseLinesOfAnObj) {
    TempDir dir;
    std::string obj;
    for (int i = 0; i < 8; ++i)
        obj += std::string("v ") + (i & 1 ? "1" : "-1") + (i & 2 ? " 1" : " -1") + (i & 4 ? " 1\n" : " -1\n");
    obj += "v -2 0 0\nv 2 0 0\nv -2 0.2 0.2\nv 0 0.2 0.2\nv 2 0.2 0.2\n";
    obj += "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
    obj += "l 9 10\nl 11 12 13\n";
    const std::string model = dir.write("box.obj", obj);
    auto r = run_cli("info " + model);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("loose line segments:  3\n"), std::string::npos) << r.out;
    r = run_cli("lines " + model + " --size 320x240 --lines contour,loose -o " + dir.file("b.svg") + " --lines-json " +
                dir.file("b.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    const auto json = nlohmann::json::parse(slurp(dir.file("b.json")));
    ASSERT_EQ(json["layers"].size(), 2u);
    EXPECT_EQ(json["layers"][1]["type"], "loose");
    EXPECT_FALSE(json["layers"][1]["paths"].empty());
}

// The rtsc line types beyond contours: each has its SVG layer with paths on the teapot, in the
// order asked for, and its JSON layer with the parameters; bad values are one-line errors.
TEST(LinesCommand, IsophotesTopoAndHighlightLayers) {
    TempDir dir;
    const std::vector<std::string> types = {"isophote", "topo", "suggestive-highlight", "principal-highlight"};
    auto r = run_cli(
        "lines builtin:teapot --size 320x240 --lines isophote,topo,suggestive-highlight,principal-highlight "
        "-o " +
        dir.file("t.svg") + " --lines-json " + dir.file("t.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir.file("t.svg"));
    size_t previous = 0;
    for (const std::string& type : types) {
        const size_t at = svg.find("<g id=\"" + type + "\"");
        ASSERT_NE(at, std::string::npos) << type;
        EXPECT_GT(at, previous) << type << " in the order asked for";
        EXPECT_EQ(svg.compare(svg.find('>', at) + 2, 7, "<path d"), 0) << type << " has paths";
        previous = at;
    }
    const auto json = nlohmann::json::parse(slurp(dir.file("t.json")));
    ASSERT_EQ(json["layers"].size(), types.size());
    EXPECT_EQ(json["layers"][0]["params"]["levels"], 20);
    EXPECT_EQ(json["layers"][1]["params"]["frame"], "camera");
    EXPECT_EQ(json["layers"][3]["params"]["threshold"], 0.04);
    for (size_t i = 0; i < types.size(); ++i) EXPECT_GT(json["layers"][i]["paths"].size(), 0u) << types[i];

    for (const std::string& set :
         std::vector<std::string>{"isophote.direction=0,0,0", "isophote.direction=1,2", "topo.spacing=0.000001",
                                  "topo.frame=sideways", "principal-highlight.convex=maybe"}) {
        r = run_cli("lines builtin:torus --lines isophote,topo,principal-highlight --set " + set + " -o " +
                    dir.file("x.svg"));
        EXPECT_EQ(r.status, 2) << set << ": " << r.err;
        EXPECT_EQ(line_count(r.err), 1) << set << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir.file("x.svg"))) << set;
    }
}

TEST(LinesCommand, BadInputIsExit2WithOneLineAndNoFile) {
    TempDir dir;
    const std::string out = dir.file("x.svg");
    for (const std::string& args : std::vector<std::string>{
             "builtin:sphere --lines scribble", "builtin:sphere --lines contour,contour", "builtin:sphere --lines ,",
             "builtin:sphere --size 0x5", "builtin:sphere --size big", "builtin:nothing", dir.file("missing.obj"),
             "builtin:sphere --set contour.wobble=1", "builtin:sphere --set contour.width=-1",
             "builtin:sphere --lines contour --set crease.angle=30", "builtin:sphere --eye 1,2",
             // Stroke parameters: a dash pattern under 1 px, a too short max-length, bad choices
             // and lists.
             "builtin:sphere --set contour.dash=0.2,0.3", "builtin:sphere --set contour.max-length=0.5",
             "builtin:sphere --set contour.cap=pointy", "builtin:sphere --set contour.depth-width=1,2,3",
             "builtin:sphere --set contour.sketch-passes=0", "builtin:sphere --set contour.dash=-4",
             "builtin:sphere --set contour.brush=felt", "builtin:sphere --set contour.brush-length=-2"}) {
        auto r = run_cli("lines " + args + " -o " + out);
        EXPECT_EQ(r.status, 2) << args << ": " << r.err;
        EXPECT_EQ(line_count(r.err), 1) << args << ": " << r.err;
        EXPECT_EQ(r.err.rfind("inkshade: ", 0), 0u) << r.err;
    }
    for (std::string target : {dir.file("no/such/dir/x.svg"), dir.path().string()}) {
        auto r = run_cli("lines builtin:sphere -o " + target);
        EXPECT_EQ(r.status, 2) << target << ": " << r.err;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
    }
    auto r = run_cli("lines builtin:sphere -o " + out + " --lines-json " + dir.file("nope/x.json"));
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << "no output after a failure";
    for (const auto& e : std::filesystem::directory_iterator(dir.path()))
        EXPECT_EQ(e.path().filename().string().find("x.svg"), std::string::npos) << e.path();
}

// A brush: the GPU strokes (lines -o x.png) take ink away inside the same outline, the SVG keeps
// the outline's path data and names the brush; a bad name lists the choices.
TEST(LinesCommand, BrushTexturesGpuStrokesAndIsNamedInTheSvg) {
    TempDir dir;
    const std::string common = "lines builtin:torus --lines contour --size 160x120 --set contour.width=6 ";
    for (const char* out : {"solid.png", "solid.svg"}) ASSERT_EQ(run_cli(common + "-o " + dir.file(out)).status, 0);
    for (const char* out : {"ink.png", "ink.svg"})
        ASSERT_EQ(run_cli(common + "--set contour.brush=ink --set contour.brush-length=30 -o " + dir.file(out)).status,
                  0);
    const Image solid = read_png(dir.file("solid.png")), ink = read_png(dir.file("ink.png"));
    int covered = 0, outside = 0, lighter = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x) {
            const int a = solid.pixel(x, y)[0], b = ink.pixel(x, y)[0];
            covered += a < 128;
            outside += a == 255 && b != 255;  // ink where the solid stroke has none
            lighter += a < 128 && b > a + 64;
        }
    EXPECT_GT(covered, 500);
    EXPECT_EQ(outside, 0);
    EXPECT_GT(lighter, covered / 10) << "the dry brush leaves gaps";
    const std::string solid_svg = slurp(dir.file("solid.svg")), ink_svg = slurp(dir.file("ink.svg"));
    EXPECT_EQ(solid_svg.find("data-brush"), std::string::npos);
    EXPECT_NE(ink_svg.find("data-brush=\"ink\" data-brush-length=\"30\""), std::string::npos);
    EXPECT_EQ(solid_svg.substr(solid_svg.find("<path")), ink_svg.substr(ink_svg.find("<path"))) << "same outline";
    const auto r = run_cli(common + "--set contour.brush=felt -o " + dir.file("x.png"));
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("'felt' is not one of none, pencil, ink, chalk, marker"), std::string::npos) << r.err;
}

// Paths are fitted cubic Béziers by default (a sphere's outline: a few C commands) and the
// polylines' points with --svg-polylines (L only), which an image output refuses.
TEST(LinesCommand, SvgPathsAreBeziersUnlessPolylinesAreAskedFor) {
    TempDir dir;
    auto r = run_cli("lines builtin:sphere --lines contour --size 200x200 -o " + dir.file("b.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli("lines builtin:sphere --lines contour --size 200x200 --svg-polylines -o " + dir.file("p.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string bezier = slurp(dir.file("b.svg")), poly = slurp(dir.file("p.svg"));
    auto path_data = [](const std::string& svg) {
        const size_t at = svg.find("<path d=\"");
        return at == std::string::npos ? std::string() : svg.substr(at + 9, svg.find('"', at + 9) - at - 9);
    };
    EXPECT_NE(path_data(bezier).find('C'), std::string::npos) << path_data(bezier);
    EXPECT_EQ(path_data(poly).find('C'), std::string::npos);
    EXPECT_NE(path_data(poly).find('L'), std::string::npos);
    EXPECT_LT(bezier.size() * 2, poly.size());
    r = run_cli("lines builtin:sphere --svg-polylines -o " + dir.file("x.png"));
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--svg-polylines"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}

// `lines -o x.png` is the stroke pass of `render` alone: over a white background its pixels are
// exactly those of `render` drawing the same line types over a white fill (ambient 1, light 0),
// for a style's lines and for --lines with a camera of its own.
void expect_same_pixels(const std::string& lines_args, const std::string& render_args) {
    TempDir dir;
    auto r = run_cli("lines " + lines_args + " -o " + dir.file("l.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli("render " + render_args + " -o " + dir.file("r.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    const Image lines = read_png(dir.file("l.png")), render = read_png(dir.file("r.png"));
    ASSERT_EQ(lines.width, 160);
    ASSERT_EQ(lines.height, 120);
    ASSERT_EQ(render.width, 160);
    ASSERT_EQ(render.height, 120);
    int dark = 0, differ = 0;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x) {
            dark += lines.pixel(x, y)[0] < 128;
            for (int c = 0; c < 4; ++c) differ += lines.pixel(x, y)[c] != render.pixel(x, y)[c];
        }
    EXPECT_GT(dark, 300) << "the drawing has lines";
    EXPECT_EQ(differ, 0) << lines_args;
}

TEST(LinesCommand, PngIsTheRenderersStrokesOfTheStylesLines) {
    expect_same_pixels("builtin:teapot --style ink-vector --size 160x120",
                       "builtin:teapot --style ink-vector --size 160x120");
}

TEST(LinesCommand, PngOfChosenLinesIsTheRenderersStrokesOverWhite) {
    const std::string view = " --size 160x120 --azimuth 20 --elevation 35 --ortho --samples 8";
    expect_same_pixels("builtin:torus --lines contour,suggestive" + view,
                       "builtin:torus --lines contour,suggestive --base-color 1,1,1 --light-color 0,0,0 --ambient "
                       "1,1,1" +
                           view);
}

// JPEG and 16-bit PNG as `render` writes them; a transparent background gives alpha 0 around
// opaque lines; what an image cannot hold is exit 2 before any work.
TEST(LinesCommand, ImageOutputsAndTheirLimits) {
    TempDir dir;
    const std::string base = "lines builtin:torus --size 96x64 ";
    auto r = run_cli(base + "--quality 80 -o " + dir.file("l.JPEG"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir.file("l.JPEG")).substr(0, 3), std::string("\xFF\xD8\xFF"));
    r = run_cli(base + "--bit-depth 16 --background transparent -o " + dir.file("l16.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    const Image wide = read_png(dir.file("l16.png"));
    ASSERT_EQ(wide.rgba16.size(), size_t(96 * 64 * 4));
    int opaque = 0;
    for (size_t i = 3; i < wide.rgba16.size(); i += 4) opaque += wide.rgba16[i] == 65535;
    EXPECT_EQ(wide.rgba16[3], 0) << "the corner is background";
    EXPECT_GT(opaque, 50) << "line pixels";

    for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
             {"-o " + dir.file("x.bmp"),
              dir.file("x.bmp") + ": cannot write '.bmp' line drawings (write .svg, .png, .jpg or .jpeg)"},
             {"-o " + dir.file("x"),
              dir.file("x") + ": cannot write line drawings without an extension (write .svg, .png, .jpg or .jpeg)"},
             {"--hidden -o " + dir.file("x.png"), "--hidden: hidden lines are drawn (dashed) in SVG only; write .svg"},
             {"--occlusion-levels 0-1 -o " + dir.file("x.png"),
              "--occlusion-levels: hidden levels are drawn (dashed) in SVG only; write .svg"},
             {"--occlusion-levels 2-1 -o " + dir.file("x.svg"),
              "occlusion levels: expected A-B with 0 <= A <= B <= 253 (0 = visible), A, or A- for A and deeper; "
              "got '2-1'"},
             {"--occlusion-levels 0-999 -o " + dir.file("x.svg"),
              "occlusion levels: expected A-B with 0 <= A <= B <= 253 (0 = visible), A, or A- for A and deeper; "
              "got '0-999'"},
             {"--quality 50 -o " + dir.file("x.svg"), "--quality: applies to .jpg and .jpeg output only"},
             {"--quality 50 -o " + dir.file("x.png"), "--quality: applies to .jpg and .jpeg output only"},
             {"--bit-depth 16 -o " + dir.file("x.svg"), "--bit-depth: applies to .png output only"},
             {"--bit-depth 16 -o " + dir.file("x.jpg"), "--bit-depth: applies to .png output only"},
             {"--bit-depth 4 -o " + dir.file("x.png"), "--bit-depth: expected 8 or 16, got 4"},
             {"--background transparent -o " + dir.file("x.jpg"),
              dir.file("x.jpg") + ": JPEG has no transparency; write .png for a transparent background"}}) {
        r = run_cli(base + args);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_EQ(r.err, "inkshade: " + message + "\n") << args;
    }
    for (const auto& e : std::filesystem::directory_iterator(dir.path()))
        EXPECT_EQ(e.path().filename().string().rfind("x", 0), std::string::npos) << e.path() << " written";
}

TEST(LinesCommand, ImageSpaceTypeIsRejectedWithChoices) {
    TempDir dir;
    // Every registered object-space type is accepted; the message for a bad name lists them.
    auto r = run_cli("lines builtin:sphere --lines nope -o " + dir.file("x.svg"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("contour"), std::string::npos) << r.err;
    // `hull` is a raster line type (GPU): `lines` points to `render`.
    r = run_cli("lines builtin:sphere --lines hull -o " + dir.file("x.svg"));
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err,
              "inkshade: --lines: 'hull' is drawn in the image by `inkshade render`, not as vector lines (choose "
              "apparent-ridge, border, cast-shadow, clip-boundary, contour, crease, external-contour, hatch, "
              "intersection, isophote, light-contour, loose, material-boundary, principal-highlight, ridge, "
              "silhouette, suggestive, suggestive-highlight, topo, valley)\n");
    // Seven object-space types at once: each has its layer, in the order given, and the
    // torus seen from 45° above (closed, smooth, no sharp edges, not crossing itself) has
    // contours, suggestive contours on its inner side and ridges, but no creases, no borders
    // and no intersections (its valleys stay under the threshold). The tube's curvature 1/r =
    // 2.5 is the same all round, so its ridges are a marginal case: at the automatic feature
    // size (about 0.03 here, from the 10th percentile of |k|) the threshold 0.1 / 0.03 is above
    // 2.5; a size of 1 % of the bounding box (0.04) brings it to 2.5.
    r = run_cli(
        "lines builtin:torus --lines contour,suggestive,crease,border,ridge,valley,intersection --size 256x256 "
        "--set ridge.feature-size=0.04 --elevation 45 -o " +
        dir.file("all.svg") + " --lines-json " + dir.file("all.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(slurp(dir.file("all.json")));
    const std::vector<std::string> types = {"contour", "suggestive", "crease",      "border",
                                            "ridge",   "valley",     "intersection"};
    ASSERT_EQ(j.at("layers").size(), types.size());
    for (size_t i = 0; i < types.size(); ++i) {
        const auto& layer = j.at("layers")[i];
        EXPECT_EQ(layer.at("type"), types[i]);
        const bool expect_lines =
            types[i] != "crease" && types[i] != "border" && types[i] != "valley" && types[i] != "intersection";
        EXPECT_EQ(!layer.at("paths").empty(), expect_lines) << types[i];
    }
}

// --svg-fill: the visible faces' region (geometry/visible_fills.hpp) in a `fills` layer under
// the strokes, filled with the style's base colour on a mesh without materials; the sphere's
// region spans its outline, as the contour does.
TEST(LinesCommand, SvgFillUnderTheStrokes) {
    TempDir dir;
    auto r = run_cli("lines builtin:sphere --size 200x200 --lines contour --base-color \"#336699\" --svg-fill -o " +
                     dir.file("f.svg") + " --lines-json " + dir.file("f.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir.file("f.svg"));
    const size_t fills = svg.find("<g id=\"fills\""), contour = svg.find("<g id=\"contour\"");
    ASSERT_NE(fills, std::string::npos);
    ASSERT_NE(contour, std::string::npos);
    EXPECT_LT(fills, contour) << "fills go under the strokes";
    const size_t path = svg.find("<path id=\"fill-0\" fill=\"#336699\" d=\"M", fills);
    ASSERT_NE(path, std::string::npos) << svg.substr(fills, 300);
    // The fill's x extent is the contour's, within a pixel.
    auto extent = [](const std::string& d) {
        std::vector<float> xs;
        std::istringstream in(d);
        std::string token;
        bool x = true;
        while (in >> token) {
            if (token == "M" || token == "L" || token == "Z") continue;
            if (token[0] == 'M' || token[0] == 'L') token = token.substr(1);
            if (x) xs.push_back(std::stof(token));
            x = !x;
        }
        return std::pair(*std::min_element(xs.begin(), xs.end()), *std::max_element(xs.begin(), xs.end()));
    };
    const size_t d = svg.find(" d=\"", path) + 4;
    const auto [lo, hi] = extent(svg.substr(d, svg.find('"', d) - d));
    const auto json = nlohmann::json::parse(slurp(dir.file("f.json")));
    float clo = 1e9f, chi = -1e9f;
    for (const auto& p : json["layers"][0]["paths"])
        for (const auto& q : p["points"]) clo = std::min(clo, q[0].get<float>()), chi = std::max(chi, q[0].get<float>());
    EXPECT_NEAR(lo, clo, 1.0f);
    EXPECT_NEAR(hi, chi, 1.0f);
    r = run_cli("lines builtin:sphere --size 200x200 --lines contour -o " + dir.file("n.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir.file("n.svg")).find("id=\"fills\""), std::string::npos);
    // An image has no SVG to fill: said, not ignored.
    r = run_cli("render builtin:sphere --size 64x64 --svg-fill -o " + dir.file("r.png"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--svg-fill: fills come with an SVG line drawing"), std::string::npos) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("r.png")));
}

}  // namespace
}  // namespace inkshade::test
