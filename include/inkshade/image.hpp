// RGBA images (8 bits a channel, optionally 16 as well) and their PNG and JPEG files.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace inkshade {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;  // row-major, top row first, 4 bytes per pixel
    // The same pixels at 16 bits a channel (0..65535), or empty. Filled by a render that asks
    // for 16 bits (RenderOptions::bit_depth) and by read_png of a 16-bit file; `rgba` then
    // holds them rounded to 8 bits, so code that reads only `rgba` sees the same picture.
    std::vector<uint16_t> rgba16;

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(size_t(w) * size_t(h) * 4, 0) {}
    uint8_t* pixel(int x, int y) { return &rgba[(size_t(y) * width + x) * 4]; }
    const uint8_t* pixel(int x, int y) const { return &rgba[(size_t(y) * width + x) * 4]; }
};

// Reverses the row order in place, of `rgba16` too (OpenGL reads pixels bottom row first).
void flip_vertically(Image& image);

// A 16-bit channel value rounded to 8 bits (v * 255 / 65535, to nearest).
inline uint8_t to_8_bits(uint16_t v) { return uint8_t((uint32_t(v) * 255u + 32767u) / 65535u); }

// Writes a PNG (libpng) atomically (temp file in the same directory, then rename), RGBA at
// `bit_depth` 8 or 16 bits a channel; 16 needs the image's `rgba16`.
// Throws RuntimeError with "FILE: reason" when it cannot.
void write_png(const std::string& path, const Image& image, int bit_depth = 8);

// JPEG (baseline, 8-bit RGB) at `quality` 1..100, written atomically; the alpha channel is
// dropped, so callers refuse images with transparency first. Throws RuntimeError.
void write_jpeg(const std::string& path, const Image& image, int quality = 95);

// The image formats the CLI writes, chosen by the output's extension (case-insensitive).
enum class ImageFormat { Png, Jpeg };
// Throws InputError("FILE: cannot write '.bmp' images (write .png, .jpg or .jpeg)").
ImageFormat image_format_of(const std::string& path);

// Reads a PNG (or JPEG) into RGBA8, and into `rgba16` as well when the file has 16 bits a
// channel (used by tests and golden comparisons). Throws InputError.
Image read_png(const std::string& path);

}  // namespace inkshade
