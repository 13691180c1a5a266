// Textures from the command line: a texture that cannot be loaded is a warning (exit 0), a
// loaded one is rendered and counted by `inkshade info`.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace inkshade::test
