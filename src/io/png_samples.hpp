// PNG files of raw samples (gray, RGB or RGBA, 8 or 16 bits), written atomically: the AOV
// images, which are not RGBA Images. Throws RuntimeError("FILE: reason").
//
// A dataset writes many of them, so they favour speed over the last few percent of size: each
// row predicted from the one above (PNG's Up filter) and zlib's run-length strategy, about a
// fifth of libpng's default time (every filter tried per row, zlib level 6) for files 4-5 %
// larger on shading and a few percent either way on ids and masks.
#pragma once
#include <cstdint>
#include <string>

namespace inkshade::io {

// `channels` 1 (gray), 3 (RGB) or 4 (RGBA) samples a pixel, rows top first.
void write_png_samples(const std::string& path, int width, int height, int channels, const uint8_t* samples);
void write_png_samples(const std::string& path, int width, int height, int channels, const uint16_t* samples);

}  // namespace inkshade::io
