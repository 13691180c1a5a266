// OpenEXR files of float32 channels (the depth and surface-field AOVs), written atomically.
#pragma once
#include <string>
#include <vector>

namespace inkshade::io {

struct ExrChannel {
    std::string name;   // "Z", "R", ...
    const float* data;  // the first pixel's sample
    size_t stride = 1;  // floats from one pixel's sample to the next
};

// Both lossless. ZIP (zlib at its fastest level over OpenEXR's byte predictor) pays for smooth
// data such as depth. Curvature fields are mantissa noise where only the background's runs
// compress: RLE keeps them within a few percent of ZIP's size at a quarter of its time.
enum class ExrCompression { Zip, Rle };

// A scan-line EXR of `channels`, FLOAT (32 bits) each, rows top first. Throws
// RuntimeError("FILE: reason").
void write_exr(const std::string& path, int width, int height, const std::vector<ExrChannel>& channels,
               ExrCompression compression = ExrCompression::Zip);

}  // namespace inkshade::io
