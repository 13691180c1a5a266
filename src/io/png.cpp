// PNG encode/decode through stb (Debian libstb); output goes through write_file_atomic.
#include <stb_image.h>
#include <stb_image_write.h>

#include <fstream>
#include <iterator>

#include "inkshade/error.hpp"
#include "inkshade/image.hpp"
#include "io/atomic_file.hpp"

namespace inkshade {

void write_png(const std::string& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != size_t(image.width) * size_t(image.height) * 4)
        throw RuntimeError(path + ": cannot write an empty or inconsistent image");
    std::string bytes;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
    };
    if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(), image.width * 4))
        throw RuntimeError(path + ": PNG encoding failed");
    io::write_file_atomic(path, bytes);
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
