// `--time SECONDS` from the command line: mtoon's UV animation scrolls a textured square by
// speed x time (a whole texture at speed 0.25 and time 4 draws the picture of time 0, half of it
// at time 2 swaps its halves); a bad time is one line and exit 2, before any file is written.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

// The square [-1, 1]^2 facing +z with uvs over the whole image, material `skin`.
const char* kQuadObj =
    "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl skin\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";

// Straight on, orthographic, the square filling the image.
const std::string kView =
    " --shading mtoon --set uv-animation-scroll-x-speed=0.25 --ortho --ortho-height 2 "
    "--eye 0,0,5 --target 0,0,0 --light-pos 0,0,10 --samples 1 --size 64x64";

struct Quad {
    TempDir dir;
    std::string obj;
    Quad() {
        // Left half red, right half blue.
        Image tex(4, 1);
        tex.rgba = {255, 0, 0, 255, 255, 0, 0, 255, 0, 0, 255, 255, 0, 0, 255, 255};
        write_png(dir.file("tex.png"), tex);
        dir.write("quad.mtl", "newmtl skin\nmap_Kd tex.png\n");
        obj = dir.write("quad.obj", kQuadObj);
    }
    Image render(const std::string& time) {
        const std::string out = dir.file("t" + time + ".png");
        auto r = run_cli("render '" + obj + "'" + kView + " --time " + time + " -o '" + out + "'");
        EXPECT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(r.err, "");
        return read_png(out);
    }
};

TEST(UvAnimationCli, TimeScrollsTheTextureBySpeedTimesTime) {
    Quad q;
    const Image still = q.render("0"), whole = q.render("4"), half = q.render("2");
    int compared = 0;
    for (int y = 4; y < 60; y += 5)
        for (int x = 4; x < 60; x += 5) {
            if (x > 26 && x < 38) continue;  // the blend between the halves
            const uint8_t* s = still.pixel(x, y);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(whole.pixel(x, y)[c]), int(s[c]), 1) << x << "," << y;
            // Half a texture on: the other half's colour.
            const uint8_t* h = half.pixel(x, y);
            EXPECT_EQ(h[0] > h[2], s[2] > s[0]) << x << "," << y;
            ++compared;
        }
    EXPECT_GE(compared, 100);
    EXPECT_GT(int(still.pixel(10, 32)[0]), int(still.pixel(10, 32)[2]) + 50);  // red on the left at time 0
}

TEST(UvAnimationCli, BadTimeIsOneLineAndExitTwo) {
    Quad q;
    for (const char* bad : {"-1", "nan", "inf"}) {
        auto r = run_cli("render '" + q.obj + "'" + kView + " --time " + bad + " -o '" + q.dir.file("a.png") + "'");
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_EQ(r.err, std::string("inkshade: --time: expected seconds >= 0, got '") + bad + "'\n") << bad;
        EXPECT_FALSE(std::filesystem::exists(q.dir.file("a.png"))) << bad;
    }
    auto text = run_cli("render '" + q.obj + "' --time soon -o '" + q.dir.file("a.png") + "'");
    EXPECT_EQ(text.status, 2);
    EXPECT_EQ(line_count(text.err), 1) << text.err;
    EXPECT_NE(text.err.find("--time"), std::string::npos) << text.err;
}

}  // namespace
}  // namespace inkshade::test
