#include "io/exr_compression.hpp"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstring>

#include "inkshade/error.hpp"

namespace inkshade::io {

namespace {

// The word-at-a-time loops below read bytes in memory order from the low end of a word.
static_assert(std::endian::native == std::endian::little, "the word loops assume little-endian order");

uint64_t load64(const uint8_t* p) {
    uint64_t v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

constexpr uint64_t kOnes = 0x0101010101010101ull, kHighs = 0x8080808080808080ull;

// The first i in [from, size − 2) where bytes i, i + 1 and i + 2 are equal, or size. Eight
// positions a step: a byte of (x ^ y) | (y ^ z) is zero where a triple starts, and the lowest
// byte the has-zero test flags is the first zero (it flags no false byte below the first).
size_t next_triple(const uint8_t* in, size_t from, size_t size) {
    size_t i = from;
    for (; i + 10 <= size; i += 8) {
        const uint64_t x = load64(in + i), y = load64(in + i + 1), z = load64(in + i + 2);
        const uint64_t v = (x ^ y) | (y ^ z);
        const uint64_t zero = (v - kOnes) & ~v & kHighs;
        if (zero) return i + (size_t(__builtin_ctzll(zero)) >> 3);
    }
    for (; i + 2 < size; ++i)
        if (in[i] == in[i + 1] && in[i + 1] == in[i + 2]) return i;
    return size;
}

// The end of the run of in[from]'s value that starts at `from`.
size_t run_end(const uint8_t* in, size_t from, size_t size) {
    const uint64_t pattern = kOnes * in[from];
    size_t i = from + 1;
    for (; i + 8 <= size; i += 8)
        if (const uint64_t d = load64(in + i) ^ pattern) return i + (size_t(__builtin_ctzll(d)) >> 3);
    while (i < size && in[i] == in[from]) ++i;
    return i;
}

// The halves (bytes 0, 2, 4, ... then 1, 3, 5, ...) into `h`, then the predictor into `t`,
// both `size` bytes; both loops vectorise. Four bytes at a time (a float's) while they last.
void predict(const uint8_t* in, size_t size, uint8_t* h, uint8_t* t) {
    if (size == 0) return;
    const size_t half = (size + 1) / 2, words = size / 4;
    for (size_t i = 0; i < words; ++i) {
        uint32_t v;
        std::memcpy(&v, in + 4 * i, 4);
        const uint16_t even = uint16_t((v & 0xffu) | ((v >> 8) & 0xff00u));
        const uint16_t odd = uint16_t(((v >> 8) & 0xffu) | ((v >> 16) & 0xff00u));
        std::memcpy(h + 2 * i, &even, 2);
        std::memcpy(h + half + 2 * i, &odd, 2);
    }
    for (size_t i = 4 * words; i < size; ++i) h[i % 2 ? half + i / 2 : i / 2] = in[i];
    t[0] = h[0];
    for (size_t i = 1; i < size; ++i) t[i] = uint8_t(h[i] - h[i - 1] + 128);
}

}  // namespace

size_t exr_rle_compress(const uint8_t* in, size_t size, std::vector<uint8_t>& scratch, uint8_t* out) {
    if (size == 0) return 0;
    scratch.resize(2 * size);
    uint8_t* t = scratch.data() + size;
    predict(in, size, scratch.data(), t);

    uint8_t* o = out;
    size_t i = 0;
    while (i < size) {
        const size_t run = next_triple(t, i, size);
        for (size_t count; i < run; i += count) {  // literals
            count = std::min<size_t>(128, run - i);
            *o++ = uint8_t(-int(count));
            std::memcpy(o, t + i, count);
            o += count;
        }
        if (run == size) break;
        const size_t end = run_end(t, run, size);
        for (size_t count; i < end; i += count) {  // the run, in pieces of at most 128
            count = std::min<size_t>(128, end - i);
            *o++ = uint8_t(count - 1);
            *o++ = t[run];
        }
    }
    return size_t(o - out);
}

ExrZipCompressor::ExrZipCompressor(int level) : stream_(std::make_unique<z_stream>()) {
    if (deflateInit(stream_.get(), level) != Z_OK) throw RuntimeError("zlib could not start a compressor");
}

ExrZipCompressor::~ExrZipCompressor() { deflateEnd(stream_.get()); }

size_t ExrZipCompressor::bound(size_t size) const { return size_t(deflateBound(stream_.get(), uLong(size))); }

size_t ExrZipCompressor::compress(const uint8_t* in, size_t size, std::vector<uint8_t>& scratch, uint8_t* out) {
    scratch.resize(2 * size);
    predict(in, size, scratch.data(), scratch.data() + size);
    z_stream& z = *stream_;
    if (deflateReset(&z) != Z_OK) throw RuntimeError("zlib could not reset its compressor");
    z.next_in = scratch.data() + size;
    z.avail_in = uInt(size);
    z.next_out = out;
    z.avail_out = uInt(bound(size));
    if (deflate(&z, Z_FINISH) != Z_STREAM_END) throw RuntimeError("zlib could not compress a chunk");
    return size_t(z.total_out);
}

}  // namespace inkshade::io
