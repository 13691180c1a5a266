// Image files through stb (Debian libstb): PNG and JPEG encoding, PNG decoding, and the format
// an output's extension asks for. Output goes through write_file_atomic.
#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "core/name_suggestion.hpp"
#include "inkshade/error.hpp"
#include "inkshade/image.hpp"
#include "io/atomic_file.hpp"
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

}  // namespace

void write_png(const std::string& path, const Image& image) {
    check_image(path, image);
    std::string bytes;
    if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(), image.width * 4))
        throw RuntimeError(path + ": PNG encoding failed");
    io::write_file_atomic(path, bytes);
}

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
    int w = 0, h = 0, comp = 0;
    unsigned char* data = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()), int(bytes.size()),
                                                &w, &h, &comp, 4);
    if (!data) throw InputError(path, std::string("not a readable PNG (") + stbi_failure_reason() + ")");
    Image image(w, h);
    std::copy(data, data + size_t(w) * size_t(h) * 4, image.rgba.begin());
    stbi_image_free(data);
    return image;
}

}  // namespace inkshade
