// OpenEXR files of float32 channels (the depth AOV), written atomically.
#pragma once
#include <string>
#include <vector>

namespace inkshade::io {

struct ExrChannel {
    std::string name;          // "Z", "R", ...
    const float* data;         // the first pixel's sample
    size_t stride = 1;         // floats from one pixel's sample to the next
};

// A scan-line EXR (ZIP compression, lossless) of `channels`, FLOAT (32 bits) each, rows top
// first. Throws RuntimeError("FILE: reason").
void write_exr(const std::string& path, int width, int height, const std::vector<ExrChannel>& channels);

}  // namespace inkshade::io
