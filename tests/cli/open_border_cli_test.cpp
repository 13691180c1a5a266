// The hull outline follows open borders: a single-sided square sheet seen from the front has no
// back face for the inverted hull to push out, so without `borders` its edge is bare (`ink`
// also finds it as a depth edge, so only the hull-only styles are compared).
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

// Dark pixels (every channel below 64) on the ring of pixels 1-3 px outside and inside the
// square's edge: the square [-1, 1]² fills 64..192 of a 256 px image (ortho height 4).
int dark_pixels_on_edge(const Image& img) {
    int dark = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const int d = std::min({std::abs(x - 64), std::abs(x - 191), std::abs(y - 64), std::abs(y - 191)});
            const bool beside = x >= 60 && x <= 195 && y >= 60 && y <= 195 && d <= 3;
            const uint8_t* p = img.pixel(x, y);
            if (beside && p[0] < 64 && p[1] < 64 && p[2] < 64) ++dark;
        }
    return dark;
}

TEST(OpenBorders, HullStylesOutlineTheEdgeOfASheet) {
    TempDir dir;
    const std::string sheet = dir.write("sheet.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n");
    const std::string camera = " --ortho --ortho-height 4 --eye 0,0,5 --target 0,0,0 --size 256x256 -o ";
    for (const char* style : {"toon", "anime"}) {
        auto r = run_cli("render " + sheet + " --style " + style + camera + dir.file("with.png"));
        ASSERT_EQ(r.status, 0) << r.err;
        r = run_cli("render " + sheet + " --style " + style + " --set hull.borders=false" + camera +
                    dir.file("without.png"));
        ASSERT_EQ(r.status, 0) << r.err;
        // Four edges of 128 px, each under a line at least 2 px wide (toon 2.5, anime 3).
        EXPECT_GE(dark_pixels_on_edge(read_png(dir.file("with.png"))), 4 * 128 * 2) << style;
        EXPECT_EQ(dark_pixels_on_edge(read_png(dir.file("without.png"))), 0) << style;
    }
}

}  // namespace
}  // namespace inkshade::test
