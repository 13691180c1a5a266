// OpenEXR's RLE compression of one chunk (the OpenEXR file layout, "RLE_COMPRESSION"), written
// here because the library's encoder goes a byte at a time: this one looks for runs eight bytes
// at a time and takes the surface-field AOVs' mantissa noise at about a third of the library's
// time (docs/benchmarks.md, "Fourth pass"). Any OpenEXR reader decodes its output.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace inkshade::io {

// The most bytes exr_rle_compress writes for `size` input bytes: every byte a literal, with one
// count byte per 128.
constexpr size_t exr_rle_bound(size_t size) { return size + (size + 127) / 128; }

// Compresses `size` bytes of a chunk's pixel data (its channels one after another, samples in
// little-endian order, as the file stores them uncompressed) into `out`, which holds
// exr_rle_bound(size) bytes; `scratch` is resized as needed. Returns the compressed size. The
// format: the bytes split into the even- and odd-indexed halves, each byte replaced by its
// difference to the one before plus 128 (mod 256), then runs of 3 to 128 equal bytes stored as
// (length − 1, byte) and everything else as (−count, count bytes), count 1 to 128. A file
// stores the chunk uncompressed when this is not smaller.
size_t exr_rle_compress(const uint8_t* in, size_t size, std::vector<uint8_t>& scratch, uint8_t* out);

}  // namespace inkshade::io
