// `inkshade render`, `info`, `styles`: exit codes, one-line errors, outputs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

TEST(RenderCommand, WritesPngOfRequestedSize) {
    TempDir dir;
    auto r = run_cli("render builtin:sphere --size 96x64 -o " + dir.file("a.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    Image img = read_png(dir.file("a.png"));
    EXPECT_EQ(img.width, 96);
    EXPECT_EQ(img.height, 64);
    // Model in the middle (not background white), white background in the corner.
    const uint8_t* c = img.pixel(48, 32);
    EXPECT_LT(int(c[0]) + c[1] + c[2], 3 * 250);
    EXPECT_EQ(img.pixel(0, 0)[0], 255);
}

// --light-intensity is the style file's [light] intensity (one request path): the same bytes,
// brighter than intensity 1; a bad value is exit 2 with one line naming the option.
TEST(RenderCommand, LightIntensityMatchesTheStyleFilesAndBrightens) {
    TempDir dir;
    const std::string base = "render builtin:sphere --size 64x64 --shading lambert --light-color 0.3,0.3,0.3 ";
    const std::string style = dir.write("bright.toml", "[light]\ncolor = \"0.3,0.3,0.3\"\nintensity = 3\n"
                                                       "[shading]\nmodel = \"lambert\"\n");
    ASSERT_EQ(run_cli(base + "--light-intensity 3 -o " + dir.file("flag.png")).status, 0);
    auto r = run_cli("render builtin:sphere --size 64x64 --style " + style + " -o " + dir.file("style.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(run_cli(base + "-o " + dir.file("one.png")).status, 0);
    EXPECT_EQ(slurp(dir.file("flag.png")), slurp(dir.file("style.png")));
    const Image bright = read_png(dir.file("flag.png")), dim = read_png(dir.file("one.png"));
    EXPECT_GT(int(bright.pixel(32, 32)[0]), int(dim.pixel(32, 32)[0]) + 60);
    auto bad = run_cli(base + "--light-intensity -2 -o " + dir.file("bad.png"));
    EXPECT_EQ(bad.status, 2);
    EXPECT_EQ(bad.err, "inkshade: --light-intensity: expected a number in [0, 1e+06], got '-2'\n");
}

TEST(RenderCommand, RepeatedSetBeforeModelTakesOneValueEach) {
    TempDir dir;
    auto r = run_cli("render --shading phong --set shininess=3 --set specular=1,0,0 builtin:sphere --size 32x32 -o " +
                     dir.file("a.png") + " --save-style " + dir.file("s.toml"));
    ASSERT_EQ(r.status, 0) << r.err;
    // Each --set took its own value (not "3 --set specular=1,0,0 builtin:sphere" as one), and
    // MODEL after them is still the model.
    const std::string style = slurp(dir.file("s.toml"));
    EXPECT_NE(style.find("\nshininess = 3 "), std::string::npos) << style;
    EXPECT_NE(style.find("\nspecular = '1,0,0' "), std::string::npos) << style;
    // And they reach the pixels: the red-only highlight of exponent 3 is wide, so somewhere on
    // the grey sphere red exceeds green by far (white and grey pixels have them equal).
    const Image img = read_png(dir.file("a.png"));
    int most = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) most = std::max(most, int(img.pixel(x, y)[0]) - int(img.pixel(x, y)[1]));
    EXPECT_GT(most, 60);
}

TEST(RenderCommand, TransparentBackgroundGivesAlphaZero) {
    TempDir dir;
    auto r = run_cli("render builtin:torus --size 64x64 --background transparent -o " + dir.file("t.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    Image img = read_png(dir.file("t.png"));
    EXPECT_EQ(img.pixel(0, 0)[3], 0);
}

TEST(RenderCommand, MissingModelFileIsExit2WithOneLine) {
    TempDir dir;
    auto r = run_cli("render " + dir.file("nope.obj") + " -o " + dir.file("a.png"));
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("inkshade: " + dir.file("nope.obj") + ":"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.png")));
}

TEST(RenderCommand, FailedRunLeavesNoPartialFile) {
    TempDir dir;
    std::string bad = dir.write("bad.stl", "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0");
    auto r = run_cli("render " + bad + " -o " + dir.file("a.png"));
    EXPECT_EQ(r.status, 2);
    for (const auto& e : std::filesystem::directory_iterator(dir.path()))
        EXPECT_EQ(e.path().filename().string().find("a.png"), std::string::npos) << e.path();
}

// The output path is checked before any work (the check `lines` uses too).
TEST(RenderCommand, BadOutputPathIsExit2BeforeRendering) {
    TempDir dir;
    for (const std::string& out : {std::string("''"), dir.path().string(), dir.file("missing/a.png")}) {
        auto r = run_cli("render builtin:sphere -o " + out);
        EXPECT_EQ(r.status, 2) << out << ": " << r.err;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
    }
    EXPECT_NE(run_cli("render builtin:sphere -o ''").err.find("-o: empty path"), std::string::npos);
}

TEST(RenderCommand, UnknownShadingModelIsExit2) {
    TempDir dir;
    auto r = run_cli("render builtin:sphere --shading glossy -o " + dir.file("a.png"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("unknown shading model 'glossy'"), std::string::npos) << r.err;
    EXPECT_EQ(line_count(r.err), 1);
}

TEST(RenderCommand, BadOptionValuesAreExit2) {
    TempDir dir;
    const std::string out = " -o " + dir.file("a.png");
    for (std::string args :
         {"--size 0x10", "--size big", "--set shininess=abc", "--shading phong --set shininess=-3",
          "--shading phong --set gloss=1", "--shading phong --set lambert.shininess=2", "--eye 1,2",
          "--light-type spot", "--background notacolour", "--fov 0", "--distance -1", "--samples 0"}) {
        auto r = run_cli("render builtin:sphere " + args + out);
        EXPECT_EQ(r.status, 2) << args << ": " << r.err;
        EXPECT_EQ(line_count(r.err), 1) << args << ": " << r.err;
        EXPECT_EQ(r.err.rfind("inkshade: ", 0), 0u) << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.png")));
}

TEST(RenderCommand, MissingOutputDirectoryIsExit2) {
    TempDir dir;
    auto r = run_cli("render builtin:sphere -o " + dir.file("no/such/dir/a.png"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
}

TEST(RenderCommand, UsageErrorsAreExit2) {
    EXPECT_EQ(run_cli("").status, 2);
    EXPECT_EQ(run_cli("render").status, 2);
    EXPECT_EQ(run_cli("render builtin:sphere").status, 2);  // no -o
    EXPECT_EQ(run_cli("frobnicate").status, 2);
    EXPECT_EQ(run_cli("render builtin:sphere -o x.png --no-such-flag").status, 2);
}

TEST(RenderCommand, HelpIsExit0ForEveryCommand) {
    for (const char* c : {"--help", "render --help", "info --help", "styles --help", "demo --help"}) {
        auto r = run_cli(c);
        EXPECT_EQ(r.status, 0) << c;
        EXPECT_NE(r.out.find("Usage"), std::string::npos) << c;
    }
}

TEST(RenderCommand, TimingPrintsMedianPerPassAndTotal) {
    TempDir dir;
    auto r = run_cli("render builtin:sphere --size 64x64 --timing 3 -o " + dir.file("a.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* pass : {"shading", "resolve", "readback", "total"})
        EXPECT_NE(r.out.find(std::string(pass) + " "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("median"), std::string::npos);
    // The total line: wall median, then the GPU time (timestamp queries) of the same frames.
    const size_t total = r.out.find("  total ");
    ASSERT_NE(total, std::string::npos);
    double wall = -1, gpu = -1;
    ASSERT_EQ(std::sscanf(r.out.c_str() + total, "  total median %lf ms gpu %lf ms", &wall, &gpu), 2) << r.out;
    EXPECT_GT(wall, 0.0);
    EXPECT_GT(gpu, 0.0);
}

TEST(RenderCommand, NoOpenGlIsExit1WithInstallHint) {
    TempDir dir;
    // An EGL vendor list with no usable driver: glvnd then offers no display at all.
    std::string empty = dir.write("none.json", "{}");
    auto r = run_cli("render builtin:sphere -o " + dir.file("a.png"),
                     "__EGL_VENDOR_LIBRARY_FILENAMES=" + empty + " __EGL_VENDOR_LIBRARY_DIRS=" + dir.path().string());
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("apt-get install"), std::string::npos) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
}

TEST(RenderCommand, StyleOptionErrorsAreExit2WithOneLine) {
    TempDir dir;
    const std::string out = " -o " + dir.file("a.png");
    auto r = run_cli("render builtin:sphere --style nope" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("cel-000"), std::string::npos) << r.err;  // lists the built-in styles
    r = run_cli("render builtin:sphere --style cel-000 --shading phong" + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("alternatives"), std::string::npos) << r.err;
    std::string bad = dir.write("bad.toml", "[shading]\nmodel = 'phong'\nshininess = -1\n");
    r = run_cli("render builtin:sphere --style " + bad + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(bad + ": parameter shininess"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("a.png")));
}

TEST(RenderCommand, SavedStyleReproducesTheSamePixels) {
    TempDir dir;
    auto r = run_cli(
        "render builtin:torus --style cel-000 --set levels=1,0.6,0.3 --set thresholds=0.7,0.4 --size 64x64 -o " +
        dir.file("a.png") + " --save-style " + dir.file("s.toml"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli("render builtin:torus --style " + dir.file("s.toml") + " --size 64x64 -o " + dir.file("b.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read_png(dir.file("a.png")).rgba, read_png(dir.file("b.png")).rgba);
}

TEST(InfoCommand, PrintsCountsAndTopologyOfBuiltinSphere) {
    auto r = run_cli("info builtin:sphere");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("euler characteristic: 2"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("boundary edges:       0"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("components:           1"), std::string::npos) << r.out;
}

TEST(InfoCommand, BadFileIsExit2) {
    TempDir dir;
    auto r = run_cli("info " + dir.write("e.ply", ""));
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(line_count(r.err), 1);
}

// Two triangles of a square, the first repeated as written and reversed.
const char* kSquareWithDuplicates = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\nf 1 2 3\nf 3 2 1\n";

TEST(InfoCommand, CountsTheDuplicateFacesTheFileHolds) {
    TempDir dir;
    const std::string obj = dir.write("dup.obj", kSquareWithDuplicates);
    auto r = run_cli("info '" + obj + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("triangles:            4\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("duplicate faces:      2\n"), std::string::npos) << r.out;
    EXPECT_EQ(r.err, "");  // nothing dropped, so nothing to warn about
}

TEST(RenderCommand, WarnsOnceAboutDroppedDuplicateFaces) {
    TempDir dir;
    const std::string obj = dir.write("dup.obj", kSquareWithDuplicates);
    auto r = run_cli("lines '" + obj + "' --size 64x64 -o " + dir.file("dup.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "inkshade: warning: " + obj +
                         ": dropped 2 duplicate faces (same vertices as an earlier face, either winding)\n");
}

// One line, exit 2, and the suggestion, for each kind of name a user can get slightly wrong.
TEST(RenderCommand, MisspeltNamesSuggestTheClosest) {
    TempDir dir;
    const std::string out = " -o " + dir.file("a.png");
    const std::pair<std::string, std::string> cases[] = {
        {"render builtin:sphere --style anmie" + out, "did you mean 'anime'?"},
        {"render builtin:sphere --shading phnog" + out, "did you mean 'phong'?"},
        {"lines builtin:sphere --lines contuor -o " + dir.file("a.svg"), "did you mean 'contour'?"},
        {"rendr", "did you mean 'render'?"},
        {"Render builtin:sphere" + out, "did you mean 'render'?"},
        {"render --szie 64x64 builtin:sphere" + out, "did you mean '--size'?"},
        {"render builtin:sphere --sampels=4" + out, "did you mean '--samples'?"},
        {"--verison", "did you mean '--version'?"},
        {"render builtin:sphere --background whiet" + out, "did you mean 'white'?"},
    };
    for (const auto& [args, suggestion] : cases) {
        auto r = run_cli(args);
        EXPECT_EQ(r.status, 2) << args << ": " << r.err;
        EXPECT_EQ(line_count(r.err), 1) << args << ": " << r.err;
        EXPECT_EQ(r.err.rfind("inkshade: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(suggestion), std::string::npos) << args << ": " << r.err;
    }
    auto bg = run_cli("render builtin:sphere --background whiet" + out);
    EXPECT_NE(bg.err.find("or a name: black, blue, cyan, gray, green, grey, magenta, orange, red, transparent, white, "
                          "yellow)"),
              std::string::npos)
        << bg.err;
}

TEST(RenderCommand, NamesWithNoCloseMatchGetNoSuggestion) {
    TempDir dir;
    const std::string out = " -o " + dir.file("a.png");
    for (const std::string& args :
         {"render builtin:sphere --style watercolour" + out, "render builtin:sphere --shading glossy" + out,
          "lines builtin:sphere --lines squiggle -o " + dir.file("a.svg"), std::string("paint"),
          "render builtin:sphere --frobnicate 3" + out, "render builtin:sphere --background plaid" + out}) {
        auto r = run_cli(args);
        EXPECT_EQ(r.status, 2) << args << ": " << r.err;
        EXPECT_EQ(line_count(r.err), 1) << args << ": " << r.err;
        EXPECT_EQ(r.err.find("did you mean"), std::string::npos) << args << ": " << r.err;
    }
}

TEST(RenderCommand, NamesIgnoreCase) {
    TempDir dir;
    EXPECT_EQ(run_cli("render builtin:sphere --size 32x32 --style Anime -o " + dir.file("a.png")).status, 0);
    EXPECT_EQ(run_cli("render builtin:sphere --size 32x32 --shading PHONG -o " + dir.file("b.png")).status, 0);
    EXPECT_EQ(run_cli("lines builtin:sphere --size 32x32 --lines Contour -o " + dir.file("c.svg")).status, 0);
}

TEST(StylesCommand, ListsEveryModelWithParameters) {
    auto r = run_cli("styles");
    ASSERT_EQ(r.status, 0);
    for (const char* m :
         {"flat", "gouraud", "lambert", "phong", "blinn-phong", "normal", "view", "w", "ndotv", "shininess"})
        EXPECT_NE(r.out.find(m), std::string::npos) << m;
}

// A box four times taller along +z than wide, as a Z-up CAD export writes it (ASCII STL, no
// normals): upright with --up-axis z, lying down without.
TEST(RenderCommand, UpAxisZStandsAZUpModelUpright) {
    TempDir dir;
    std::string stl = "solid tall\n";
    const float x0 = 0, x1 = 1, y0 = 0, y1 = 1, z0 = 0, z1 = 4;
    const float v[8][3] = {{x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0},
                           {x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}};
    const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                              {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    for (const auto& f : faces) {
        stl += "facet normal 0 0 0\nouter loop\n";
        for (int k : f)
            stl += "vertex " + std::to_string(v[k][0]) + " " + std::to_string(v[k][1]) + " " + std::to_string(v[k][2]) +
                   "\n";
        stl += "endloop\nendfacet\n";
    }
    const std::string model = dir.write("tall.stl", stl + "endsolid tall\n");
    auto extent = [&](const std::string& options) {  // width and height of the non-white pixels
        const std::string png = dir.file("a.png");
        const auto r =
            run_cli("render " + model + " --size 96x96 --azimuth 20 --elevation 10 " + options + " -o " + png);
        EXPECT_EQ(r.status, 0) << r.err;
        const Image image = read_png(png);
        int x_min = image.width, x_max = -1, y_min = image.height, y_max = -1;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                if (image.pixel(x, y)[0] < 250) {
                    x_min = std::min(x_min, x), x_max = std::max(x_max, x);
                    y_min = std::min(y_min, y), y_max = std::max(y_max, y);
                }
        return std::pair<int, int>(x_max - x_min + 1, y_max - y_min + 1);
    };
    const auto [w_up, h_up] = extent("--up-axis z");
    EXPECT_GT(h_up, 2 * w_up);  // standing
    const auto [w_flat, h_flat] = extent("");
    EXPECT_GT(w_flat, h_flat);  // lying along the view's horizontal
    // A style may say the up axis; the option wins over it.
    const std::string style = dir.write("z.toml", "up-axis = \"z\"\n[shading]\nmodel = \"lambert\"\n");
    EXPECT_EQ(extent("--style " + style), std::make_pair(w_up, h_up));
    EXPECT_EQ(extent("--style " + style + " --up-axis y"), std::make_pair(w_flat, h_flat));
    const std::string bad_style = dir.write("w.toml", "up-axis = \"w\"\n[shading]\nmodel = \"lambert\"\n");
    const auto bad_file = run_cli("render " + model + " --style " + bad_style + " -o " + dir.file("b.png"));
    EXPECT_EQ(bad_file.status, 2);
    EXPECT_NE(bad_file.err.find("up-axis: expected"), std::string::npos) << bad_file.err;
    const auto bad = run_cli("render " + model + " --up-axis w -o " + dir.file("b.png"));
    EXPECT_EQ(bad.status, 2);
    EXPECT_NE(bad.err.find("--up-axis: expected x, y, z, -x, -y or -z, got 'w'"), std::string::npos) << bad.err;
}

// --lines adds line types to any style; --set then reaches them.
TEST(RenderCommand, LinesOptionAddsLineTypesToTheStyle) {
    TempDir dir;
    const std::string base = "render builtin:torus --size 96x96 --style mtoon --samples 1";
    auto r = run_cli(base + " -o " + dir.file("plain.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli(base + " --lines hull --set hull.width=4 --set hull.color=1,0,0 -o " + dir.file("hull.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    const Image plain = read_png(dir.file("plain.png")), hull = read_png(dir.file("hull.png"));
    int red = 0;  // the outline's pure red, which mtoon's shading of the torus never gives
    for (int y = 0; y < hull.height; ++y)
        for (int x = 0; x < hull.width; ++x) {
            const auto h = hull.pixel(x, y), p = plain.pixel(x, y);
            red += h[0] == 255 && h[1] == 0 && h[2] == 0 && !(p[0] == 255 && p[1] == 0 && p[2] == 0);
        }
    EXPECT_GT(red, 100);
    r = run_cli(base + " --lines hul -o " + dir.file("x.png"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("did you mean 'hull'?"), std::string::npos) << r.err;
}

TEST(RenderCommand, HelpListsEveryReadableFormat) {
    const auto r = run_cli("render --help");
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* ext : {".obj", ".stl", ".ply", ".off", ".gltf", ".glb", ".vrm"})
        EXPECT_NE(r.out.find(ext), std::string::npos) << ext;
#ifdef INKSHADE_HAVE_ASSIMP
    EXPECT_NE(r.out.find(".fbx"), std::string::npos);  // assimp's importers
    EXPECT_NE(r.out.find(".dae"), std::string::npos);
#endif
}

// The output's extension chooses the format; anything else fails before any work.
TEST(RenderCommand, OutputFormatFollowsTheExtension) {
    TempDir dir;
    const std::string base = "render builtin:torus --size 64x48 --style cel-000 ";
    auto r = run_cli(base + "-o " + dir.file("a.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli(base + "-o " + dir.file("a.JPG"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string jpeg = slurp(dir.file("a.JPG"));
    ASSERT_GT(jpeg.size(), 3u);
    EXPECT_EQ(jpeg.substr(0, 3), std::string("\xFF\xD8\xFF"));                         // JPEG's start-of-image marker
    const Image png = read_png(dir.file("a.png")), jpg = read_png(dir.file("a.JPG"));  // stb decodes both
    ASSERT_EQ(jpg.width, 64);
    ASSERT_EQ(jpg.height, 48);
    double error = 0.0;
    for (size_t i = 0; i < png.rgba.size(); ++i)
        if (i % 4 != 3) error += std::abs(int(png.rgba[i]) - int(jpg.rgba[i]));
    EXPECT_LT(error / double(png.width * png.height * 3), 4.0);  // quality 95: a few levels at most
    r = run_cli(base + "--quality 20 -o " + dir.file("b.jpeg"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_LT(slurp(dir.file("b.jpeg")).size(), jpeg.size());

    for (const std::string& bad :
         {base + "-o " + dir.file("c.bmp"), base + "-o " + dir.file("c"), base + "--quality 50 -o " + dir.file("c.png"),
          base + "--background transparent -o " + dir.file("c.jpg")}) {
        r = run_cli(bad);
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
    }
    EXPECT_NE(
        run_cli(base + "-o " + dir.file("c.bmp")).err.find("cannot write '.bmp' images (write .png, .jpg or .jpeg)"),
        std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir.file("c.bmp")));
    EXPECT_FALSE(std::filesystem::exists(dir.file("c.jpg")));
}

// Either output that cannot be written, of `render` or of `lines`, leaves no file at all.
TEST(RenderCommand, EveryOutputIsCheckedBeforeWork) {
    TempDir dir;
    const std::string missing = dir.file("missing/x");
    const std::vector<std::string> runs = {
        "render builtin:sphere --size 16x16 -o " + dir.file("a.png") + " --save-style " + missing + ".toml",
        "render builtin:sphere --size 16x16 -o " + missing + ".png --save-style " + dir.file("s.toml"),
        "render builtin:sphere --size 16x16 -o " + dir.file("a.jpg") + " --save-style " + missing + ".toml",
        "lines builtin:sphere --size 16x16 -o " + dir.file("l.png") + " --lines-json " + missing + ".json",
        "lines builtin:sphere --size 16x16 -o " + dir.file("l.svg") + " --lines-json " + missing + ".json",
        "lines builtin:sphere --size 16x16 -o " + missing + ".png --lines-json " + dir.file("l.json"),
        "lines builtin:sphere --size 16x16 -o " + missing + ".svg --lines-json " + dir.file("l.json"),
    };
    for (const std::string& run : runs) {
        const CliResult r = run_cli(run);
        EXPECT_EQ(r.status, 2) << run;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(dir.file("missing")), std::string::npos) << r.err;
        EXPECT_TRUE(std::filesystem::is_empty(dir.path())) << run << " left a file";
    }
}

// --bit-depth 16: a 16-bit PNG (IHDR bit depth 16) whose values, scaled, are the 8-bit PNG's
// within one level; only for PNG, and only 8 or 16.
TEST(RenderCommand, BitDepth16WritesA16BitPng) {
    TempDir dir;
    const std::string base = "render builtin:sphere --size 64x48 ";
    auto r = run_cli(base + "--bit-depth 16 -o " + dir.file("wide.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli(base + "-o " + dir.file("narrow.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string bytes = slurp(dir.file("wide.png"));
    ASSERT_GT(bytes.size(), 26u);
    EXPECT_EQ(bytes.substr(12, 4), "IHDR");
    EXPECT_EQ(int(uint8_t(bytes[24])), 16) << "bit depth";
    EXPECT_EQ(int(uint8_t(bytes[25])), 6) << "RGBA";
    EXPECT_EQ(int(uint8_t(slurp(dir.file("narrow.png"))[24])), 8);
    const Image wide = read_png(dir.file("wide.png")), narrow = read_png(dir.file("narrow.png"));
    ASSERT_EQ(wide.rgba16.size(), size_t(64 * 48 * 4));
    EXPECT_TRUE(narrow.rgba16.empty());
    int off = 0, shaded = 0, finer = 0;
    for (size_t i = 0; i < narrow.rgba.size(); ++i) {
        off += std::abs(wide.rgba16[i] / 257.0 - narrow.rgba[i]) > 1.0;
        if (narrow.rgba[i] == 255) continue;  // background white is 65535 in both
        ++shaded;
        finer += wide.rgba16[i] % 257 != 0;  // not a widened 8-bit value
    }
    EXPECT_EQ(off, 0);
    EXPECT_GT(shaded, 1000) << "the sphere";
    EXPECT_GT(finer, 0.9 * shaded) << "the 16-bit file carries levels between the 8-bit ones";

    for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
             {"--bit-depth 16 -o " + dir.file("c.jpg"), "--bit-depth: applies to .png output only"},
             {"--bit-depth 8 -o " + dir.file("c.jpeg"), "--bit-depth: applies to .png output only"},
             {"--bit-depth 12 -o " + dir.file("c.png"), "--bit-depth: expected 8 or 16, got 12"}}) {
        r = run_cli(base + args);
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_EQ(r.err, "inkshade: " + message + "\n") << args;
    }
    for (const char* name : {"c.jpg", "c.jpeg", "c.png"}) EXPECT_FALSE(std::filesystem::exists(dir.file(name)));
}

}  // namespace
}  // namespace inkshade::test
