// The `hatching` shading model from the command line: its fill is the formula, its strokes
// are the `hatch` lines (the overlay with `lines` is in lines_overlay_test.cpp).
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

size_t differing_pixels(const Image& a, const Image& b) {
    size_t n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (a.pixel(x, y)[c] != b.pixel(x, y)[c]) {
                    ++n;
                    break;
                }
    return n;
}

// wash = 1 and no stroke level (tones = 0: no tone is below 0) leave C*(E*max(n.l,0) + A):
// lambert's image, pixel for pixel. With the default tones the strokes darken pixels of it.
TEST(HatchingCli, FullWashWithoutStrokesIsLambert) {
    TempDir dir;
    const std::string common = "render builtin:sphere --size 160x120 --base-color 1,1,1 ";
    ASSERT_EQ(run_cli(common + "--shading lambert -o " + dir.file("l.png")).status, 0);
    CliResult r =
        run_cli(common + "--shading hatching --set hatching.wash=1 --set hatching.tones=0 -o " + dir.file("h.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli(common + "--shading hatching --set hatching.wash=1 -o " + dir.file("s.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    const Image l = read_png(dir.file("l.png")), h = read_png(dir.file("h.png")), s = read_png(dir.file("s.png"));
    EXPECT_EQ(differing_pixels(l, h), 0u);
    EXPECT_GT(differing_pixels(l, s), 500u) << "the strokes are drawn";
}

// `lines --lines hatch` writes a hatch layer of paths; a bad parameter is a one-line error.
TEST(HatchingCli, LinesWritesHatchLayerAndRejectsBadValues) {
    TempDir dir;
    CliResult r = run_cli("lines builtin:sphere --lines contour,hatch --size 200x200 -o " + dir.file("h.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string svg = slurp(dir.file("h.svg"));
    const size_t layer = svg.find("<g id=\"hatch\"");
    ASSERT_NE(layer, std::string::npos);
    size_t paths = 0;
    for (size_t at = svg.find("<path", layer); at != std::string::npos; at = svg.find("<path", at + 1)) ++paths;
    EXPECT_GT(paths, 20u);
    r = run_cli("lines builtin:sphere --lines hatch --set hatch.levels=9 -o " + dir.file("bad.svg"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("levels"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("bad.svg")));
}

}  // namespace
}  // namespace inkshade::test
