// scripts/avatar-sample, the VRM 1.0 avatar of the mtoon gallery: `info` lists what its pose
// options take, and its happy expression changes the face as the script's morph targets say
// (the eyes close from ellipses into thin arcs a quarter as tall).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

// Where the script puts the head (world space: the Hips node at y 0.35, the head 0.87 above it)
// and the eyes (head-local x +-0.11, y 0; radii 0.05 x 0.075).
constexpr double kHeadY = 1.22, kEyeX = 0.11, kEyeRx = 0.05, kEyeRy = 0.075;
// Front orthographic view of the head: 400 px for 0.8 m, 500 px a metre.
constexpr int kSize = 400;
constexpr double kPixelsPerMetre = kSize / 0.8;

std::string write_avatar(const TempDir& dir) {
    const std::string path = dir.file("avatar.vrm");
    const std::string cmd =
        "python3 '" + std::string(INKSHADE_SOURCE_DIR) + "/scripts/avatar-sample' '" + path + "' >/dev/null";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    return path;
}

// Pixels of the eyes' near-black colour in a box around each eye.
int dark_eye_pixels(const Image& image) {
    int count = 0;
    for (double ex : {-kEyeX, kEyeX}) {
        const int cx = int(std::lround(kSize / 2.0 + ex * kPixelsPerMetre)), cy = kSize / 2;
        for (int y = cy - 45; y <= cy + 45; ++y)
            for (int x = cx - 35; x <= cx + 35; ++x) {
                const uint8_t* p = image.pixel(x, y);
                count += p[0] < 80 && p[1] < 80 && p[2] < 80;
            }
    }
    return count;
}

TEST(AvatarSample, InfoListsItsAnimationMorphTargetsAndExpressions) {
    TempDir dir;
    const CliResult r = run_cli("info '" + write_avatar(dir) + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("\nanimations:           1\n"
                         "  0 'wave': 1 s\n"
                         "morph targets:        2\n"
                         "  'happy'\n"
                         "  'blink'\n"
                         "expressions:          2\n"
                         "  'blink' (preset)\n"
                         "  'happy' (preset)\n"
                         "load time:"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\ntextures:             2\n"), std::string::npos) << r.out;  // the two matcaps
}

TEST(AvatarSample, HappyClosesTheEyesIntoArcs) {
    TempDir dir;
    const std::string avatar = write_avatar(dir);
    const std::string view = " --style mtoon --ortho --ortho-height 0.8 --azimuth 0 --elevation 0 --target 0," +
                             std::to_string(kHeadY) + ",0 --size " + std::to_string(kSize) + "x" +
                             std::to_string(kSize) + " -o ";
    auto r = run_cli("render '" + avatar + "'" + view + dir.file("rest.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli("render '" + avatar + "' --expression happy=1" + view + dir.file("happy.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    const int rest = dark_eye_pixels(read_png(dir.file("rest.png")));
    const int happy = dark_eye_pixels(read_png(dir.file("happy.png")));
    // At rest each eye shows the part of its ellipsoid in front of the head: the ellipse out to
    // 0.88 of its radii (its centre 0.012 behind the head's surface, its depth radius 0.025).
    const double rest_area = 2 * M_PI * kEyeRx * kEyeRy * 0.77 * kPixelsPerMetre * kPixelsPerMetre;
    EXPECT_NEAR(rest, rest_area, 0.25 * rest_area);
    // Happy scales the eyes' height by 0.25 and bends them into arcs: a quarter of the area.
    EXPECT_NEAR(double(happy) / double(rest), 0.25, 0.1) << happy << " of " << rest;
}

}  // namespace
}  // namespace inkshade::test
