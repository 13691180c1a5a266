#include "inkshade/contact_sheet.hpp"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>

#include "inkshade/error.hpp"

namespace inkshade {

namespace {

constexpr int kPad = 8;  // pixels around each tile and its caption

int caption_height(int text_scale) { return 12 * text_scale + 2 * kPad; }

// Fills the axis-aligned quads stb_easy_font produces (4 vertices of 16 bytes each).
void draw_text(Image& img, int x0, int y0, const std::string& text, int scale) {
    std::vector<char> buffer(text.size() * 270 + 64);  // ~270 bytes per char (stb docs)
    std::string copy = text;
    unsigned char color[4] = {0, 0, 0, 255};
    int quads = stb_easy_font_print(0, 0, copy.data(), color, buffer.data(), int(buffer.size()));
    for (int q = 0; q < quads; ++q) {
        const float* v = reinterpret_cast<const float*>(buffer.data() + q * 64);
        // Vertex i at v + 4 * i (x, y, z, colour packed in the fourth float slot).
        float minx = std::min({v[0], v[4], v[8], v[12]}), maxx = std::max({v[0], v[4], v[8], v[12]});
        float miny = std::min({v[1], v[5], v[9], v[13]}), maxy = std::max({v[1], v[5], v[9], v[13]});
        for (int y = int(miny * scale); y < int(maxy * scale); ++y)
            for (int x = int(minx * scale); x < int(maxx * scale); ++x) {
                int px = x0 + x, py = y0 + y;
                if (px < 0 || py < 0 || px >= img.width || py >= img.height) continue;
                uint8_t* p = img.pixel(px, py);
                p[0] = p[1] = p[2] = 0;
                p[3] = 255;
            }
    }
}

}  // namespace

glm::ivec2 contact_sheet_tile_origin(size_t index, size_t count, int columns, glm::ivec2 tile_size, int text_scale) {
    const size_t cols = size_t(std::clamp(columns, 1, int(std::max<size_t>(count, 1))));
    return {kPad + int(index % cols) * (tile_size.x + kPad),
            kPad + int(index / cols) * (tile_size.y + caption_height(text_scale))};
}

Image contact_sheet(const std::vector<LabelledImage>& tiles, int columns, int text_scale) {
    if (tiles.empty() || columns <= 0) throw RuntimeError("contact sheet needs at least one image");
    const int w = tiles[0].image.width, h = tiles[0].image.height;
    for (const auto& t : tiles)
        if (t.image.width != w || t.image.height != h) throw RuntimeError("contact sheet images differ in size");
    const int rows = (int(tiles.size()) + columns - 1) / columns;
    const int cols = std::min(columns, int(tiles.size()));
    Image sheet(cols * (w + kPad) + kPad, rows * (h + caption_height(text_scale)) + kPad);
    std::fill(sheet.rgba.begin(), sheet.rgba.end(), uint8_t(255));
    for (size_t i = 0; i < tiles.size(); ++i) {
        const glm::ivec2 origin = contact_sheet_tile_origin(i, tiles.size(), columns, {w, h}, text_scale);
        const int x0 = origin.x, y0 = origin.y;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const uint8_t* src = tiles[i].image.pixel(x, y);
                uint8_t* dst = sheet.pixel(x0 + x, y0 + y);
                // Composite over white so transparent renders read well on the sheet.
                for (int c = 0; c < 3; ++c) dst[c] = uint8_t((src[c] * src[3] + 255 * (255 - src[3]) + 127) / 255);
                dst[3] = 255;
            }
        const int text_w = stb_easy_font_width(const_cast<char*>(tiles[i].label.c_str())) * text_scale;
        draw_text(sheet, x0 + std::max(0, (w - text_w) / 2), y0 + h + kPad, tiles[i].label, text_scale);
    }
    return sheet;
}

}  // namespace inkshade
