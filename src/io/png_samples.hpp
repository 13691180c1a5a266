// PNG files of raw samples (gray, RGB or RGBA, 8 or 16 bits), written atomically: the AOV
// images, which are not RGBA Images. Throws RuntimeError("FILE: reason").
#pragma once
#include <cstdint>
#include <string>

namespace inkshade::io {

// `channels` 1 (gray), 3 (RGB) or 4 (RGBA) samples a pixel, rows top first.
void write_png_samples(const std::string& path, int width, int height, int channels, const uint8_t* samples);
void write_png_samples(const std::string& path, int width, int height, int channels, const uint16_t* samples);

}  // namespace inkshade::io
