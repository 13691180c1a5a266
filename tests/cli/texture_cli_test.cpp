// Textures from the command line: a texture that cannot be loaded is a warning (exit 0), a
// loaded one is rendered and counted by `inkshade info`, its texels come back unlit in either
// colour convention, a preset's base colour does not tint it (an explicit --base-color
// does), and `ink` fills it white.
#include <gtest/gtest.h>

#include <cmath>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

// The square [-1, 1]^2 facing +z with uvs over the whole image and material `skin`.
const char* kQuadObj =
    "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl skin\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";

// Lit by ambient 1 only, orthographic, straight on: pixels are the base colour.
const std::string kFlatLight = " --shading lambert --light-color 0 --ambient 1 --ortho --samples 1 --size 64x64";

TEST(TextureCli, MissingMapKdIsAWarningAndTheRenderSucceeds) {
    TempDir dir;
    dir.write("quad.mtl", "newmtl skin\nKd 0.2 0.4 0.6\nmap_Kd missing.png\n");
    std::string obj = dir.write("quad.obj", kQuadObj);
    auto r = run_cli("render '" + obj + "'" + kFlatLight + " -o '" + dir.file("out.png") + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("inkshade: warning: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("missing.png"), std::string::npos) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    // The base colour stays.
    Image img = read_png(dir.file("out.png"));
    EXPECT_NEAR(int(img.pixel(32, 32)[0]), 51, 1);
    EXPECT_NEAR(int(img.pixel(32, 32)[2]), 153, 1);

    auto info = run_cli("info '" + obj + "'");
    ASSERT_EQ(info.status, 0) << info.err;
    EXPECT_NE(info.err.find("inkshade: warning: "), std::string::npos) << info.err;
    EXPECT_NE(info.out.find("textures:             0\n"), std::string::npos) << info.out;
}

TEST(TextureCli, MapKdIsRenderedAndCounted) {
    TempDir dir;
    // Left half red, right half blue (4 x 1 texels: pure colours around u = 0.25 and 0.75).
    Image tex(4, 1);
    tex.rgba = {255, 0, 0, 255, 255, 0, 0, 255, 0, 0, 255, 255, 0, 0, 255, 255};
    write_png(dir.file("tex.png"), tex);
    dir.write("quad.mtl", "newmtl skin\nmap_Kd tex.png\n");
    std::string obj = dir.write("quad.obj", kQuadObj);
    auto r = run_cli("render '" + obj + "'" + kFlatLight + " -o '" + dir.file("out.png") + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    Image img = read_png(dir.file("out.png"));
    // Well inside each half (bilinear filtering blends only near the middle and, wrapping
    // around, near the edges).
    const uint8_t* left = img.pixel(20, 32);
    const uint8_t* right = img.pixel(44, 32);
    EXPECT_GT(int(left[0]), 200);
    EXPECT_LT(int(left[2]), 55);
    EXPECT_LT(int(right[0]), 55);
    EXPECT_GT(int(right[2]), 200);

    auto info = run_cli("info '" + obj + "'");
    ASSERT_EQ(info.status, 0) << info.err;
    EXPECT_NE(info.out.find("textures:             1\n"), std::string::npos) << info.out;
}

// A 4 x 4 texture of one colour, (108,173,223), on the quad: written and referenced by quad.mtl.
constexpr uint8_t kTexel[3] = {108, 173, 223};
// Pixels well inside the quad, away from its edges and outline.
constexpr int kInside[3][2] = {{32, 32}, {20, 40}, {44, 24}};
std::string textured_quad(const TempDir& dir) {
    Image tex(4, 4);
    tex.rgba.clear();
    for (int i = 0; i < 16; ++i) tex.rgba.insert(tex.rgba.end(), {kTexel[0], kTexel[1], kTexel[2], 255});
    write_png(dir.file("tex.png"), tex);
    dir.write("quad.mtl", "newmtl skin\nmap_Kd tex.png\n");
    return dir.write("quad.obj", kQuadObj);
}

// `inkshade render OBJ ARGS` to out.png, read back.
Image render(const TempDir& dir, const std::string& obj, const std::string& args) {
    const std::string out = dir.file("out.png");
    auto r = run_cli("render '" + obj + "' --ortho --samples 1 --size 64x64 " + args + " -o '" + out + "'");
    EXPECT_EQ(r.status, 0) << args << ": " << r.err;
    return read_png(out);
}

TEST(TextureCli, UnlitTexelsComeBackInBothConventions) {
    TempDir dir;
    const std::string obj = textured_quad(dir);
    // Display convention (lambert under ambient 1 alone: C as stored), its --srgb linear
    // twin (decoded, encoded), and threejs-basic (unlit, linear: decoded, encoded).
    for (const char* args :
         {"--shading lambert --light-color 0 --ambient 1", "--shading lambert --light-color 0 --ambient 1 --srgb",
          "--shading threejs-basic", "--shading threejs-basic --srgb"}) {
        Image img = render(dir, obj, args);
        for (const auto& [x, y] : kInside)
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(int(img.pixel(x, y)[k]), int(kTexel[k]), 1)
                    << args << " at (" << x << "," << y << ") channel " << k;
    }
}

TEST(TextureCli, PresetBaseColourTintsOnlyMeshesWithoutColoursOfTheirOwn) {
    TempDir dir;
    const std::string textured = textured_quad(dir);
    const std::string plain = dir.write("plain.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n");
    // anime's base colour (0.95,0.75,0.55) leaves the textured quad as a white one would.
    Image preset = render(dir, textured, "--style anime");
    EXPECT_EQ(preset.rgba, render(dir, textured, "--style anime --base-color 1,1,1").rgba);
    // An explicit --base-color multiplies: half the red, the rest as it was.
    Image half_red = render(dir, textured, "--style anime --base-color 0.5,1,1");
    const uint8_t* was = preset.pixel(32, 32);
    const uint8_t* now = half_red.pixel(32, 32);
    EXPECT_GT(int(was[0]), 60);  // lit: halving shows
    EXPECT_NEAR(int(now[0]), int(std::lround(0.5 * was[0])), 1);
    EXPECT_NEAR(int(now[1]), int(was[1]), 1);
    EXPECT_NEAR(int(now[2]), int(was[2]), 1);
    // A mesh without colours of its own takes the preset's tint: warm, not grey.
    const Image plain_image = render(dir, plain, "--style anime");  // kept: pixel() points into it
    const uint8_t* tinted = plain_image.pixel(32, 32);
    EXPECT_GT(int(tinted[0]), int(tinted[1]) + 20);
    EXPECT_GT(int(tinted[1]), int(tinted[2]) + 20);
}

TEST(TextureCli, InkFillsATexturedMeshWhite) {
    TempDir dir;
    const std::string obj = textured_quad(dir);
    for (const char* style : {"ink", "ink-vector"}) {
        Image img = render(dir, obj, std::string("--style ") + style);
        for (const auto& [x, y] : kInside)
            for (int k = 0; k < 3; ++k)
                EXPECT_EQ(int(img.pixel(x, y)[k]), 255) << style << " at (" << x << "," << y << ")";
    }
    // --base-color gives ink another fill colour; the texture still stays out.
    Image red = render(dir, obj, "--style ink --base-color 1,0.5,0");
    EXPECT_EQ(int(red.pixel(32, 32)[0]), 255);
    EXPECT_NEAR(int(red.pixel(32, 32)[1]), 128, 1);
    EXPECT_EQ(int(red.pixel(32, 32)[2]), 0);
}

}  // namespace
}  // namespace inkshade::test
