// OpenEXR's lossless chunk compressions RLE_COMPRESSION and ZIP_COMPRESSION (the OpenEXR file
// layout), written here because OpenEXR 3.1's encoders are slow on the float fields: the C++
// library's RLE goes a byte at a time after copying each line through its frame-buffer slices,
// and the C core's ZIP took five times the C++ library's time. Both compressions first split a
// chunk's bytes into the even- and odd-indexed halves and replace each byte by its difference
// to the one before plus 128 (mod 256); the loops here vectorise and the RLE looks for runs
// eight bytes at a time (docs/benchmarks.md, "Fourth pass"). Any OpenEXR reader decodes the
// output; a file stores a chunk uncompressed when its compression is not smaller.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

struct z_stream_s;  // zlib.h

namespace inkshade::io {

// The most bytes exr_rle_compress writes for `size` input bytes: every byte a literal, with one
// count byte per 128.
constexpr size_t exr_rle_bound(size_t size) { return size + (size + 127) / 128; }

// Compresses `size` bytes of a chunk's pixel data (its lines one after another, each line's
// channels one after another, samples in little-endian order, as the file stores them
// uncompressed) into `out`, which holds exr_rle_bound(size) bytes; `scratch` is resized as
// needed. Returns the compressed size. After the predictor: runs of 3 to 128 equal bytes
// stored as (length − 1, byte) and everything else as (−count, count bytes), count 1 to 128.
size_t exr_rle_compress(const uint8_t* in, size_t size, std::vector<uint8_t>& scratch, uint8_t* out);

// ZIP: the same data after the predictor as one zlib stream a chunk, at `level` (1 fastest, 9
// smallest). One compressor serves all chunks of a file: zlib's state is reset, not made anew,
// for each (a new one cost more than the compression, in allocations and page faults).
class ExrZipCompressor {
public:
    explicit ExrZipCompressor(int level);  // throws RuntimeError when zlib cannot start
    ~ExrZipCompressor();
    ExrZipCompressor(const ExrZipCompressor&) = delete;
    ExrZipCompressor& operator=(const ExrZipCompressor&) = delete;

    // The most bytes compress writes for `size` input bytes.
    size_t bound(size_t size) const;
    // Compresses `size` bytes into `out` (bound(size) bytes); `scratch` is resized as needed.
    // Returns the compressed size; throws RuntimeError when zlib fails.
    size_t compress(const uint8_t* in, size_t size, std::vector<uint8_t>& scratch, uint8_t* out);

private:
    std::unique_ptr<z_stream_s> stream_;
};

}  // namespace inkshade::io
