// `inkshade demo` (what `make run` shows first): every tile of the contact sheet, and every
// single render beside it, shows its model against its background.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "cli/run_cli.hpp"
#include "inkshade/contact_sheet.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

constexpr int kTile = 64;

// The share of a region's pixels that stand out from its background, taken as the colour most
// pixels of its border have (the auto-framed model leaves a margin). A pixel stands out when
// a channel differs by more than a fifth of the range: antialiasing, paper grain and dithering
// of a background stay under that, a model drawn on it (fill or lines) does not.
double model_share(const Image& image, int x0, int y0, int w, int h) {
    auto rgb = [&](int x, int y) {
        const uint8_t* p = image.pixel(x0 + x, y0 + y);
        return (uint32_t(p[0]) << 16) | (uint32_t(p[1]) << 8) | p[2];
    };
    std::map<uint32_t, int> border;
    for (int i = 0; i < w; ++i) ++border[rgb(i, 0)], ++border[rgb(i, h - 1)];
    for (int i = 0; i < h; ++i) ++border[rgb(0, i)], ++border[rgb(w - 1, i)];
    const uint32_t background =
        std::max_element(border.begin(), border.end(), [](auto& a, auto& b) { return a.second < b.second; })->first;
    int model = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const uint32_t c = rgb(x, y);
            int differs = 0;
            for (int shift : {16, 8, 0})
                differs |= std::abs(int((c >> shift) & 255) - int((background >> shift) & 255)) > 51;
            model += differs;
        }
    return double(model) / double(w * h);
}

TEST(DemoCommand, EveryTileShowsItsModel) {
    TempDir dir;
    const std::string out = dir.file("out");
    CliResult r = run_cli("demo --size " + std::to_string(kTile) + " --out " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> renders;
    for (const auto& entry : std::filesystem::directory_iterator(out))
        if (entry.path().extension() == ".png" && entry.path().stem() != "contact_sheet")
            renders.push_back(entry.path().string());
    ASSERT_GT(renders.size(), 20u);
    // The teapot covers about a third of a tile; its lines alone a few percent.
    for (const std::string& path : renders) {
        const Image image = read_png(path);
        EXPECT_GT(model_share(image, 0, 0, image.width, image.height), 0.02) << path;
    }
    const Image sheet = read_png(out + "/contact_sheet.png");
    // The columns the demo chose: the sheet's width is that of its first row of tiles.
    int columns = 1;
    while (contact_sheet_tile_origin(size_t(columns), renders.size(), columns + 1, {kTile, kTile}).x + kTile <
           sheet.width)
        ++columns;
    for (size_t i = 0; i < renders.size(); ++i) {
        const glm::ivec2 at = contact_sheet_tile_origin(i, renders.size(), columns, {kTile, kTile});
        ASSERT_LE(at.x + kTile, sheet.width);
        ASSERT_LE(at.y + kTile, sheet.height);
        EXPECT_GT(model_share(sheet, at.x, at.y, kTile, kTile), 0.02) << "tile " << i << " at " << at.x << "," << at.y;
    }
}

}  // namespace
}  // namespace inkshade::test
