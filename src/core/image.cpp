#include <cstring>

#include "inkshade/image.hpp"

namespace inkshade {

namespace {

template <typename T>
void flip_rows(std::vector<T>& pixels, int width, int height) {
    const size_t row = size_t(width) * 4;
    std::vector<T> tmp(row);
    for (int y = 0; y < height / 2; ++y) {
        T* a = pixels.data() + size_t(y) * row;
        T* b = pixels.data() + size_t(height - 1 - y) * row;
        std::memcpy(tmp.data(), a, row * sizeof(T));
        std::memcpy(a, b, row * sizeof(T));
        std::memcpy(b, tmp.data(), row * sizeof(T));
    }
}

}  // namespace

void flip_vertically(Image& image) {
    flip_rows(image.rgba, image.width, image.height);
    if (!image.rgba16.empty()) flip_rows(image.rgba16, image.width, image.height);
}

}  // namespace inkshade
