#include "inkshade/contact_sheet.hpp"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>

#include "inkshade/error.hpp"

namespace inkshade {

namespace {

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

Image contact_sheet(const std::vector<LabelledImage>& tiles, int columns, int text_scale) {
    if (tiles.empty() || columns <= 0) throw RuntimeError("contact sheet needs at least one image");
    const int w = tiles[0].image.width, h = tiles[0].image.height;
    for (const auto& t : tiles)
        if (t.image.width != w || t.image.height != h) throw RuntimeError("contact sheet images differ in size");
    const int pad = 8, caption = 12 * text_scale + 2 * pad;
    const int rows = (int(tiles.size()) + columns - 1) / columns;
    const int cols = std::min(columns, int(tiles.size()));
    Image sheet(cols * (w + pad) + pad, rows * (h + caption) + pad);
    std::fill(sheet.rgba.begin(), sheet.rgba.end(), uint8_t(255));
    for (size_t i = 0; i < tiles.size(); ++i) {
        const int x0 = pad + int(i % size_t(cols)) * (w + pad), y0 = pad + int(i / size_t(cols)) * (h + caption);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const uint8_t* src = tiles[i].image.pixel(x, y);
                uint8_t* dst = sheet.pixel(x0 + x, y0 + y);
                // Composite over white so transparent renders read well on the sheet.
                for (int c = 0; c < 3; ++c) dst[c] = uint8_t((src[c] * src[3] + 255 * (255 - src[3]) + 127) / 255);
                dst[3] = 255;
            }
        const int text_w = stb_easy_font_width(const_cast<char*>(tiles[i].label.c_str())) * text_scale;
        draw_text(sheet, x0 + std::max(0, (w - text_w) / 2), y0 + h + pad, tiles[i].label, text_scale);
    }
    return sheet;
}

}  // namespace inkshade
