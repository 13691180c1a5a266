// Image files: PNG encoding through libpng (8 or 16 bits a channel; stb writes only 8), JPEG
// encoding and PNG decoding through stb (Debian libstb), and the format an output's extension
// asks for. Output goes through write_file_atomic.
#include <png.h>
#include <stb_image.h>
#include <stb_image_write.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <csetjmp>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "core/name_suggestion.hpp"
#include "inkshade/error.hpp"
#include "inkshade/image.hpp"
#include "io/atomic_file.hpp"
#include "io/png_samples.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {

namespace {

// stb's write-to-function callback: appends the encoded bytes to a std::string.
void append(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
}

void check_image(const std::string& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != size_t(image.width) * size_t(image.height) * 4)
        throw RuntimeError(path + ": cannot write an empty or inconsistent image");
}

// libpng's output and errors: bytes appended to `bytes`; an error's message kept for the throw
// after libpng has jumped back out (png_error longjmps, which no C++ exception may cross).
struct PngSink {
    std::string bytes;
    std::string error;
};

void png_append(png_structp png, png_bytep data, size_t size) {
    auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
    bool failed = false;
    try {
        sink->bytes.append(reinterpret_cast<const char*>(data), size);
    } catch (const std::exception&) {
        failed = true;
    }
    if (failed) png_error(png, "out of memory");
}

[[noreturn]] void png_fail(png_structp png, png_const_charp message) {
    auto* sink = static_cast<PngSink*>(png_get_error_ptr(png));
    try {
        sink->error = message;
    } catch (const std::exception&) {
    }
    png_longjmp(png, 1);
}

void png_ignore_warning(png_structp, png_const_charp) {}

// The encoding proper. libpng's errors longjmp back to the setjmp here, so no object with a
// destructor lives in between; false on error (the message is in the sink).
bool encode_png(png_structp png, png_infop info, int width, int height, int bit_depth, int color_type, png_bytepp rows,
                bool fast) {
    if (setjmp(png_jmpbuf(png))) return false;
    if (fast) {  // io/png_samples.hpp: the AOV images
        png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
        png_set_compression_strategy(png, Z_RLE);
    }
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), bit_depth, color_type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    return true;
}

// Encodes rows of `channels` samples a pixel (1 gray, 3 RGB, 4 RGBA) and writes them atomically.
void write_png_rows(const std::string& path, int width, int height, int channels, int bit_depth, uint8_t* pixels,
                    bool fast = false) {
    const int color_type = channels == 1   ? PNG_COLOR_TYPE_GRAY
                           : channels == 3 ? PNG_COLOR_TYPE_RGB
                                           : PNG_COLOR_TYPE_RGBA;
    const size_t row_bytes = size_t(width) * size_t(channels) * size_t(bit_depth / 8);
    std::vector<png_bytep> rows(static_cast<size_t>(height));
    for (size_t y = 0; y < rows.size(); ++y) rows[y] = pixels + y * row_bytes;

    PngSink sink;
    sink.bytes.reserve(row_bytes * rows.size() / 2 + 4096);  // most of its growth copies spared
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, png_fail, png_ignore_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        throw RuntimeError(path + ": PNG encoding failed (out of memory)");
    }
    png_set_write_fn(png, &sink, png_append, nullptr);
    const bool encoded = encode_png(png, info, width, height, bit_depth, color_type, rows.data(), fast);
    png_destroy_write_struct(&png, &info);
    if (!encoded) throw RuntimeError(path + ": PNG encoding failed (" + sink.error + ")");
    io::write_file_atomic(path, sink.bytes);
}

// PNG stores 16-bit samples most significant byte first, whatever the machine's order: a byte
// swap a sample on little-endian machines (a loop that vectorises).
std::vector<uint16_t> big_endian(const uint16_t* samples, size_t count) {
    std::vector<uint16_t> out(samples, samples + count);
    if constexpr (std::endian::native == std::endian::little)
        for (uint16_t& v : out) v = uint16_t((v >> 8) | (v << 8));
    return out;
}

}  // namespace

void write_png(const std::string& path, const Image& image, int bit_depth) {
    check_image(path, image);
    if (bit_depth != 8 && bit_depth != 16)
        throw RuntimeError(path + ": PNG bit depth must be 8 or 16, got " + std::to_string(bit_depth));
    if (bit_depth == 16 && image.rgba16.size() != image.rgba.size())
        throw RuntimeError(path + ": a 16-bit PNG needs the image's 16-bit pixels (render with 16 bits)");
    if (bit_depth == 16) {
        std::vector<uint16_t> bytes = big_endian(image.rgba16.data(), image.rgba16.size());
        return write_png_rows(path, image.width, image.height, 4, 16, reinterpret_cast<uint8_t*>(bytes.data()));
    }
    // libpng takes non-const row pointers but only reads them when writing.
    write_png_rows(path, image.width, image.height, 4, 8, const_cast<uint8_t*>(image.rgba.data()));
}

namespace io {

void write_png_samples(const std::string& path, int width, int height, int channels, const uint8_t* samples) {
    write_png_rows(path, width, height, channels, 8, const_cast<uint8_t*>(samples), true);
}

void write_png_samples(const std::string& path, int width, int height, int channels, const uint16_t* samples) {
    std::vector<uint16_t> bytes = big_endian(samples, size_t(width) * size_t(height) * size_t(channels));
    write_png_rows(path, width, height, channels, 16, reinterpret_cast<uint8_t*>(bytes.data()), true);
}

}  // namespace io

void write_jpeg(const std::string& path, const Image& image, int quality) {
    check_image(path, image);
    std::vector<unsigned char> rgb(size_t(image.width) * size_t(image.height) * 3);
    for (size_t i = 0, n = rgb.size() / 3; i < n; ++i) std::copy_n(&image.rgba[4 * i], 3, &rgb[3 * i]);
    std::string bytes;
    if (!stbi_write_jpg_to_func(append, &bytes, image.width, image.height, 3, rgb.data(), std::clamp(quality, 1, 100)))
        throw RuntimeError(path + ": JPEG encoding failed");
    io::write_file_atomic(path, bytes);
}

ImageFormat image_format_of(const std::string& path) {
    const std::string ext = lower_ascii(std::filesystem::path(path).extension().string());
    if (ext == ".png") return ImageFormat::Png;
    if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::Jpeg;
    throw InputError(path,
                     "cannot write " +
                         (ext.empty() ? std::string("images without an extension") : io::quote_token(ext) + " images") +
                         " (write .png, .jpg or .jpeg)");
}

Image read_png(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "cannot open file");
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const int size = int(bytes.size());
    int w = 0, h = 0, comp = 0;
    if (stbi_is_16_bit_from_memory(data, size)) {
        stbi_us* wide = stbi_load_16_from_memory(data, size, &w, &h, &comp, 4);
        if (!wide) throw InputError(path, std::string("not a readable PNG (") + stbi_failure_reason() + ")");
        Image image(w, h);
        image.rgba16.assign(wide, wide + size_t(w) * size_t(h) * 4);
        stbi_image_free(wide);
        std::transform(image.rgba16.begin(), image.rgba16.end(), image.rgba.begin(), to_8_bits);
        return image;
    }
    unsigned char* pixels = stbi_load_from_memory(data, size, &w, &h, &comp, 4);
    if (!pixels) throw InputError(path, std::string("not a readable PNG (") + stbi_failure_reason() + ")");
    Image image(w, h);
    std::copy(pixels, pixels + size_t(w) * size_t(h) * 4, image.rgba.begin());
    stbi_image_free(pixels);
    return image;
}

}  // namespace inkshade
