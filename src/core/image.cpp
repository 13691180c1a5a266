#include <cstring>

#include "inkshade/image.hpp"

namespace inkshade {

void flip_vertically(Image& image) {
    const size_t row = size_t(image.width) * 4;
    std::vector<uint8_t> tmp(row);
    for (int y = 0; y < image.height / 2; ++y) {
        uint8_t* a = image.rgba.data() + size_t(y) * row;
        uint8_t* b = image.rgba.data() + size_t(image.height - 1 - y) * row;
        std::memcpy(tmp.data(), a, row);
        std::memcpy(a, b, row);
        std::memcpy(b, tmp.data(), row);
    }
}

}  // namespace inkshade
