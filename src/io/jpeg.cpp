// JPEG output through stb (Debian libstb); image formats by extension.
#include <stb_image_write.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "inkshade/error.hpp"
#include "inkshade/image.hpp"
#include "io/atomic_file.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {

void write_jpeg(const std::string& path, const Image& image, int quality) {
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != size_t(image.width) * size_t(image.height) * 4)
        throw RuntimeError(path + ": cannot write an empty or inconsistent image");
    std::vector<unsigned char> rgb(size_t(image.width) * size_t(image.height) * 3);
    for (size_t i = 0, n = rgb.size() / 3; i < n; ++i) std::copy_n(&image.rgba[4 * i], 3, &rgb[3 * i]);
    std::string bytes;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
    };
    if (!stbi_write_jpg_to_func(append, &bytes, image.width, image.height, 3, rgb.data(),
                                std::clamp(quality, 1, 100)))
        throw RuntimeError(path + ": JPEG encoding failed");
    io::write_file_atomic(path, bytes);
}

ImageFormat image_format_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".png") return ImageFormat::Png;
    if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::Jpeg;
    throw InputError(path, "cannot write " + (ext.empty() ? std::string("images without an extension")
                                                            : io::quote_token(ext) + " images") +
                               " (write .png, .jpg or .jpeg)");
}

}  // namespace inkshade
