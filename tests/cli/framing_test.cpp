// Auto-framing as rendered: the model (framed by its vertices, whose projection's hull is its
// silhouette) fills the image up to --margin on the limiting axis, on both sides within one
// pixel, and is centred on the other, in wide and tall images, perspective and orthographic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

// A 2 x 1 x 0.6 box away from the origin, so centring on the origin or on the box centre's
// projection would show.
const char* kBoxObj =
    "v 2 -1 0.5\nv 4 -1 0.5\nv 4 0 0.5\nv 2 0 0.5\nv 2 -1 1.1\nv 4 -1 1.1\nv 4 0 1.1\nv 2 0 1.1\n"
    "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n";

struct Margins {
    int left, right, top, bottom;  // pixels between the model's covered pixels and each border
};

Margins measure(const Image& image) {
    int x0 = image.width, x1 = -1, y0 = image.height, y1 = -1;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (image.pixel(x, y)[3] > 0) {  // transparent background: alpha is coverage
                x0 = std::min(x0, x), x1 = std::max(x1, x);
                y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
    return {x0, image.width - 1 - x1, y0, image.height - 1 - y1};
}

void expect_framed(const std::string& size, int width, int height, const std::string& options, double margin,
                   const std::string& builtin = "") {
    TempDir dir;
    const std::string model = builtin.empty() ? dir.write("box.obj", kBoxObj) : builtin, out = dir.file("box.png");
    const CliResult r = run_cli("render " + model + " --size " + size + " --samples 1 --background transparent " +
                                options + " -o " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    const Image image = read_png(out);
    ASSERT_EQ(image.width, width);
    const Margins m = measure(image);
    SCOPED_TRACE(model + " " + size + " " + options);
    const double want_x = margin * width, want_y = margin * height;
    // The limiting axis is the one whose free space is the margin; the other has more.
    const bool horizontal =
        std::abs(m.left - want_x) + std::abs(m.right - want_x) < std::abs(m.top - want_y) + std::abs(m.bottom - want_y);
    if (horizontal) {
        EXPECT_NEAR(m.left, want_x, 1.0);
        EXPECT_NEAR(m.right, want_x, 1.0);
        EXPECT_NEAR(m.top, m.bottom, 1.0) << "centred vertically";
        EXPECT_GE(m.top, want_y - 1.0);
    } else {
        EXPECT_NEAR(m.top, want_y, 1.0);
        EXPECT_NEAR(m.bottom, want_y, 1.0);
        EXPECT_NEAR(m.left, m.right, 1.0) << "centred horizontally";
        EXPECT_GE(m.left, want_x - 1.0);
    }
}

TEST(Framing, WideImageBoxTouchesTheDefaultMargin) {
    expect_framed("1920x1080", 1920, 1080, "", 0.05);
    expect_framed("1920x1080", 1920, 1080, "--ortho", 0.05);
}

TEST(Framing, TallImageBoxTouchesTheMarginGiven) {
    expect_framed("540x960", 540, 960, "--margin 0.2", 0.2);
    expect_framed("540x960", 540, 960, "--ortho --margin 0.2 --azimuth 80 --elevation 50", 0.2);
    expect_framed("540x960", 540, 960, "--margin 0 --azimuth -30 --elevation 10 --fov 60", 0.0);
}

// Round and irregular models reach the margin themselves, not only their bounding box.
TEST(Framing, BuiltinModelsTouchTheMargin) {
    expect_framed("960x540", 960, 540, "", 0.05, "builtin:sphere");
    expect_framed("540x960", 540, 960, "--elevation 40", 0.05, "builtin:teapot");
    expect_framed("960x540", 960, 540, "--ortho --margin 0.1 --azimuth 200", 0.1, "builtin:torus-knot");
}

TEST(Framing, MarginOutsideItsRangeIsExit2) {
    TempDir dir;
    for (const char* value : {"0.5", "-0.1", "nan"}) {
        const CliResult r =
            run_cli(std::string("render builtin:sphere --size 8x8 --margin ") + value + " -o " + dir.file("x.png"));
        EXPECT_EQ(r.status, 2) << value;
        EXPECT_EQ(r.err, std::string("inkshade: --margin: expected a fraction of the image in [0, 0.5), got '") + value +
                             "'\n")
            << value;
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
}

}  // namespace
}  // namespace inkshade::test
