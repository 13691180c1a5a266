// RGBA8 images and PNG output.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace inkshade {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;  // row-major, top row first, 4 bytes per pixel

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(size_t(w) * size_t(h) * 4, 0) {}
    uint8_t* pixel(int x, int y) { return &rgba[(size_t(y) * width + x) * 4]; }
    const uint8_t* pixel(int x, int y) const { return &rgba[(size_t(y) * width + x) * 4]; }
};

// Reverses the row order in place (OpenGL reads pixels bottom row first).
void flip_vertically(Image& image);

// Writes a PNG atomically (temp file in the same directory, then rename).
// Throws RuntimeError with "FILE: reason" when it cannot.
void write_png(const std::string& path, const Image& image);

// JPEG (baseline, 8-bit RGB) at `quality` 1..100, written atomically; the alpha channel is
// dropped, so callers refuse images with transparency first. Throws RuntimeError.
void write_jpeg(const std::string& path, const Image& image, int quality = 95);

// The image formats the CLI writes, chosen by the output's extension (case-insensitive).
enum class ImageFormat { Png, Jpeg };
// Throws InputError("FILE: cannot write '.bmp' images (write .png, .jpg or .jpeg)").
ImageFormat image_format_of(const std::string& path);

// Reads a PNG into RGBA8 (used by tests and golden comparisons). Throws InputError.
Image read_png(const std::string& path);

}  // namespace inkshade
