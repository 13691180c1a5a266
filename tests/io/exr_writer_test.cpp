// The EXR writer (io/exr_writer.hpp) and its chunk compressions (io/exr_compression.hpp): files
// read back by OpenEXR's own C++ reader, sample for sample, and the codecs' bytes against the
// format.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>

#include "cli/exr_channel.hpp"
#include "inkshade/error.hpp"
#include "io/exr_compression.hpp"
#include "io/exr_writer.hpp"
#include "support/temp_dir.hpp"

namespace inkshade {
namespace {

namespace fs = std::filesystem;

// The predictor undone and the halves interleaved again, as a reader does after decompressing.
std::vector<uint8_t> unpredict(std::vector<uint8_t> t, size_t size) {
    EXPECT_EQ(t.size(), size);
    t.resize(size);
    for (size_t i = 1; i < t.size(); ++i) t[i] = uint8_t(t[i - 1] + t[i] - 128);
    std::vector<uint8_t> out(t.size());
    const size_t half = (size + 1) / 2;
    for (size_t i = 0; i < size; ++i) out[i] = i % 2 ? t[half + i / 2] : t[i / 2];
    return out;
}

// The RLE format's decoder: runs and literals, then the predictor undone.
std::vector<uint8_t> rle_decode(const std::vector<uint8_t>& in, size_t size) {
    std::vector<uint8_t> t;
    for (size_t i = 0; i < in.size();) {
        const int count = int(int8_t(in[i++]));
        if (count < 0) {
            t.insert(t.end(), in.begin() + std::ptrdiff_t(i), in.begin() + std::ptrdiff_t(i) - count);
            i += size_t(-count);
        } else {
            t.insert(t.end(), size_t(count) + 1, in[i++]);
        }
    }
    return unpredict(std::move(t), size);
}

std::vector<uint8_t> compress(const std::vector<uint8_t>& in) {
    std::vector<uint8_t> scratch, out(io::exr_rle_bound(in.size()));
    out.resize(io::exr_rle_compress(in.data(), in.size(), scratch, out.data()));
    return out;
}

TEST(ExrRle, ZerosAreOneLiteralAndRunsOf128) {
    // Zeros: the predictor keeps byte 0 and makes every other byte 128; 999 of them are seven
    // runs of 128 and one of 103.
    const std::vector<uint8_t> zeros(1000, 0);
    const std::vector<uint8_t> out = compress(zeros);
    std::vector<uint8_t> want = {uint8_t(-1), 0};
    for (int k = 0; k < 7; ++k) want.insert(want.end(), {127, 128});
    want.insert(want.end(), {102, 128});
    EXPECT_EQ(out, want);
    EXPECT_EQ(rle_decode(out, zeros.size()), zeros);
}

TEST(ExrRle, NoiseIsLiteralsOf128AtMostTheBound) {
    std::mt19937 random(7);
    std::vector<uint8_t> noise(1003);
    for (uint8_t& b : noise) b = uint8_t(random());
    const std::vector<uint8_t> out = compress(noise);
    EXPECT_LE(out.size(), io::exr_rle_bound(noise.size()));
    EXPECT_GE(out.size(), noise.size());
    EXPECT_EQ(rle_decode(out, noise.size()), noise);
}

TEST(ExrRle, RunsAndLiteralsOfEveryLengthRoundTrip) {
    // Runs of 1 to 300 equal predicted bytes between literals, at every alignment to the eight
    // bytes a step of the search: sizes odd and even.
    std::mt19937 random(11);
    for (size_t size : {size_t(1), size_t(2), size_t(3), size_t(9), size_t(17), size_t(4097)}) {
        std::vector<uint8_t> in(size);
        size_t i = 0;
        while (i < size) {
            const size_t run = 1 + random() % 300, literal = random() % 20;
            const uint8_t value = uint8_t(random());
            for (size_t k = 0; k < run && i < size; ++k) in[i++] = value;
            for (size_t k = 0; k < literal && i < size; ++k) in[i++] = uint8_t(random());
        }
        const std::vector<uint8_t> out = compress(in);
        EXPECT_LE(out.size(), io::exr_rle_bound(size));
        EXPECT_EQ(rle_decode(out, size), in) << size << " bytes";
    }
}

TEST(ExrZip, ZlibStreamOfThePredictedBytes) {
    std::mt19937 random(13);
    std::vector<uint8_t> in(5000);
    for (size_t i = 0; i < in.size(); ++i) in[i] = i % 3 ? uint8_t(i / 50) : uint8_t(random());
    io::ExrZipCompressor zip(1);
    std::vector<uint8_t> scratch;
    for (size_t size : {in.size(), in.size() / 3}) {  // a chunk, then a shorter one (zlib reset between)
        std::vector<uint8_t> out(zip.bound(size));
        out.resize(zip.compress(in.data(), size, scratch, out.data()));
        ASSERT_LT(out.size(), size);
        std::vector<uint8_t> t(size);
        uLongf got = uLongf(t.size());
        ASSERT_EQ(uncompress(t.data(), &got, out.data(), uLong(out.size())), Z_OK);
        EXPECT_EQ(unpredict(t, size_t(got)), std::vector<uint8_t>(in.begin(), in.begin() + std::ptrdiff_t(size)));
    }
}

// Rows of zeros, of one repeated value, of noise, and a mix with NaN and infinities: every
// kind of chunk (compressed, stored raw because RLE does not shrink it).
std::vector<float> test_pixels(int width, int height, int channels) {
    std::mt19937 random(3);
    std::uniform_real_distribution<float> value(-1e3f, 1e3f);
    std::vector<float> v(size_t(width) * size_t(height) * size_t(channels));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width * channels; ++x) {
            float& p = v[size_t(y) * size_t(width * channels) + size_t(x)];
            switch (y % 4) {
                case 0: p = 0.0f; break;
                case 1: p = 0.25f; break;
                case 2: p = value(random); break;
                default:
                    p = x % 7 == 0   ? std::numeric_limits<float>::quiet_NaN()
                        : x % 7 == 1 ? std::numeric_limits<float>::infinity()
                        : x < width  ? 0.0f
                                     : value(random);
            }
        }
    return v;
}

void expect_same(const std::vector<float>& got, const float* want, size_t stride, size_t count) {
    ASSERT_EQ(got.size(), count);
    for (size_t i = 0; i < count; ++i)
        ASSERT_EQ(std::memcmp(&got[i], want + i * stride, sizeof(float)), 0) << "sample " << i;
}

TEST(ExrWriter, BothCompressionsReadBackBitForBit) {
    const test::TempDir dir;
    const int width = 37, height = 9;  // a line is not a multiple of the search's eight bytes
    const std::vector<float> gray = test_pixels(width, height, 1), pair = test_pixels(width, height, 2);
    for (io::ExrCompression compression : {io::ExrCompression::Rle, io::ExrCompression::Zip}) {
        const std::string one = dir.file("one.exr"), two = dir.file("two.exr");
        io::write_exr(one, width, height, {{"Y", gray.data(), 1}}, compression);
        // Given Y before X: the file orders channels by name.
        io::write_exr(two, width, height, {{"Y", pair.data() + 1, 2}, {"X", pair.data(), 2}}, compression);
        int w = 0, h = 0;
        expect_same(test::read_exr_channel(one, "Y", w, h), gray.data(), 1, gray.size());
        EXPECT_EQ(w, width);
        EXPECT_EQ(h, height);
        expect_same(test::read_exr_channel(two, "X", w, h), pair.data(), 2, gray.size());
        expect_same(test::read_exr_channel(two, "Y", w, h), pair.data() + 1, 2, gray.size());
    }
}

TEST(ExrWriter, ChunksThatDoNotShrinkAreStoredAsTheyAre) {
    // Random bits: neither RLE nor zlib makes a chunk smaller, and the file stores it raw.
    const test::TempDir dir;
    const int width = 40, height = 20;
    std::mt19937 random(17);
    std::vector<float> v(size_t(width) * size_t(height));
    for (float& x : v) {
        const uint32_t bits = random() & 0x7f7fffffu;  // finite, whatever the mantissa
        std::memcpy(&x, &bits, sizeof x);
    }
    for (io::ExrCompression compression : {io::ExrCompression::Rle, io::ExrCompression::Zip}) {
        const std::string path = dir.file("noise.exr");
        io::write_exr(path, width, height, {{"Y", v.data(), 1}}, compression);
        EXPECT_GT(fs::file_size(path), v.size() * sizeof(float));
        int w = 0, h = 0;
        expect_same(test::read_exr_channel(path, "Y", w, h), v.data(), 1, v.size());
    }
}

TEST(ExrWriter, RleShrinksTheBackground) {
    const test::TempDir dir;
    // A field over a quarter of the image: the zero rows compress to a few bytes each.
    const int width = 256, height = 256;
    std::vector<float> v(size_t(width) * size_t(height), 0.0f);
    std::mt19937 random(5);
    for (int y = 0; y < height / 2; ++y)
        for (int x = 0; x < width / 2; ++x) v[size_t(y) * size_t(width) + size_t(x)] = float(random()) / 7.0f;
    const std::string path = dir.file("field.exr");
    io::write_exr(path, width, height, {{"Y", v.data(), 1}}, io::ExrCompression::Rle);
    EXPECT_LT(fs::file_size(path), v.size() * sizeof(float) / 3);
    int w = 0, h = 0;
    expect_same(test::read_exr_channel(path, "Y", w, h), v.data(), 1, v.size());
}

TEST(ExrWriter, EmptyImageAndUnwritableDirectoryAreErrors) {
    const test::TempDir dir;
    const float one = 1.0f;
    EXPECT_THROW(io::write_exr(dir.file("a.exr"), 0, 1, {{"Y", &one, 1}}), RuntimeError);
    EXPECT_THROW(io::write_exr(dir.file("no/a.exr"), 1, 1, {{"Y", &one, 1}}), RuntimeError);
    EXPECT_FALSE(fs::exists(dir.file("no")));
}

}  // namespace
}  // namespace inkshade
