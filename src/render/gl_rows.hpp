// GL reads images bottom row first; the AOV buffers are top row first.
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

namespace inkshade::render {

// Rows of `row_values` values, bottom row first as GL reads them, into top row first.
template <class T>
void flip_rows(std::vector<T>& v, size_t row_values) {
    const size_t rows = v.size() / row_values;
    for (size_t y = 0; y < rows / 2; ++y)
        std::swap_ranges(v.begin() + std::ptrdiff_t(y * row_values), v.begin() + std::ptrdiff_t((y + 1) * row_values),
                         v.begin() + std::ptrdiff_t((rows - 1 - y) * row_values));
}

}  // namespace inkshade::render
