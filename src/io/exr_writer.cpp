// EXR through OpenEXR's C core (OpenEXRCore, Debian libopenexr-dev), encoded in memory so the
// file is written atomically like every other output. The core writes the header and the chunk
// table, the chunks are compressed by io/exr_compression.hpp (docs/benchmarks.md, "Fourth
// pass").
#include "io/exr_writer.hpp"

#include <OpenEXR/openexr.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <optional>

#include "inkshade/error.hpp"
#include "io/atomic_file.hpp"
#include "io/exr_compression.hpp"

namespace inkshade::io {

namespace {

// zlib's fastest level: on float fields (mantissa noise) level 1 is within a few percent of the
// default's size at a fraction of its time (a dataset writes many of them).
constexpr int kZipLevel = 1;

// The file's bytes, written by the core at offsets (its chunk table is filled in last), and
// the first error it reported.
struct ExrSink {
    std::string bytes;
    std::string error;
};

int64_t write_at(exr_const_context_t, void* user, const void* buffer, uint64_t size, uint64_t offset,
                 exr_stream_error_func_ptr_t) {
    auto& sink = *static_cast<ExrSink*>(user);
    const char* bytes = static_cast<const char*>(buffer);
    try {
        if (offset == sink.bytes.size()) {  // the chunks come in order: no zero-fill first
            sink.bytes.append(bytes, size_t(size));
            return int64_t(size);
        }
        if (offset + size > sink.bytes.size()) sink.bytes.resize(size_t(offset + size));
    } catch (const std::exception&) {
        return -1;  // the core reports a write error
    }
    std::memcpy(sink.bytes.data() + offset, bytes, size_t(size));
    return int64_t(size);
}

// The core reports errors here instead of printing them.
void keep_error(exr_const_context_t context, exr_result_t code, const char* message) {
    void* user = nullptr;
    if (exr_get_user_data(context, &user) != EXR_ERR_SUCCESS || !user) return;
    auto& sink = *static_cast<ExrSink*>(user);
    if (sink.error.empty()) sink.error = message ? message : exr_get_default_error_message(code);
}

// Owns the write context: exr_finish completes the file (its chunk table) or, after a failure,
// releases it.
class ExrContext {
public:
    explicit ExrContext(ExrSink& sink) : sink_(sink) {
        exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
        init.user_data = &sink;
        init.write_fn = write_at;
        init.error_handler_fn = keep_error;
        check(exr_start_write(&context_, "memory", EXR_WRITE_FILE_DIRECTLY, &init));
    }
    ~ExrContext() {
        if (context_) exr_finish(&context_);
    }
    ExrContext(const ExrContext&) = delete;
    ExrContext& operator=(const ExrContext&) = delete;

    void check(exr_result_t result) const {
        if (result == EXR_ERR_SUCCESS) return;
        throw RuntimeError(sink_.error.empty() ? exr_get_default_error_message(result) : sink_.error);
    }
    void finish() {
        exr_context_t c = context_;
        context_ = nullptr;
        check(exr_finish(&c));
    }
    exr_context_t get() const { return context_; }

private:
    ExrSink& sink_;
    exr_context_t context_ = nullptr;
};

// Every chunk of the one scan-line part (RLE: a line each, ZIP: 16), compressed here and handed
// to the core as it is. A chunk holds its lines in order, each line its channels in the file's
// order (by name), each channel a line of little-endian floats.
void encode(const ExrContext& exr, int width, int height, const std::vector<ExrChannel>& channels,
            ExrCompression compression) {
    static_assert(std::endian::native == std::endian::little, "EXR samples are little-endian");
    const exr_context_t c = exr.get();
    const exr_attr_chlist_t* list = nullptr;
    exr.check(exr_get_channels(c, 0, &list));
    std::vector<const ExrChannel*> order;
    for (int k = 0; k < list->num_channels; ++k) {
        const std::string name(list->entries[k].name.str, size_t(list->entries[k].name.length));
        const auto in = std::find_if(channels.begin(), channels.end(), [&](const ExrChannel& ch) { return ch.name == name; });
        if (in == channels.end()) throw RuntimeError("no channel " + name);
        order.push_back(&*in);
    }
    int32_t lines = 1;
    exr.check(exr_get_scanlines_per_chunk(c, 0, &lines));
    const size_t w = size_t(width), line_floats = w * order.size();
    const size_t most = size_t(lines) * line_floats * sizeof(float);
    std::vector<float> chunk(size_t(lines) * line_floats);
    std::optional<ExrZipCompressor> zip;
    if (compression == ExrCompression::Zip) zip.emplace(kZipLevel);
    std::vector<uint8_t> scratch, packed(zip ? zip->bound(most) : exr_rle_bound(most));
    for (int y0 = 0; y0 < height; y0 += lines) {
        const int count = std::min(lines, height - y0);
        float* to = chunk.data();
        for (int y = y0; y < y0 + count; ++y)
            for (const ExrChannel* ch : order) {
                const float* from = ch->data + ch->stride * w * size_t(y);
                if (ch->stride == 1)
                    to = std::copy(from, from + w, to);
                else
                    for (size_t x = 0; x < w; ++x) *to++ = from[x * ch->stride];
            }
        const auto* raw = reinterpret_cast<const uint8_t*>(chunk.data());
        const size_t bytes = size_t(count) * line_floats * sizeof(float);
        const size_t size = zip ? zip->compress(raw, bytes, scratch, packed.data())
                                : exr_rle_compress(raw, bytes, scratch, packed.data());
        exr.check(size < bytes ? exr_write_scanline_chunk(c, 0, y0, packed.data(), size)
                               : exr_write_scanline_chunk(c, 0, y0, raw, bytes));
    }
}

}  // namespace

void write_exr(const std::string& path, int width, int height, const std::vector<ExrChannel>& channels,
               ExrCompression compression) {
    if (width <= 0 || height <= 0 || channels.empty()) throw RuntimeError(path + ": cannot write an empty EXR image");
    ExrSink sink;
    sink.bytes.reserve(size_t(width) * size_t(height) * sizeof(float) * channels.size() + 4096);
    try {
        ExrContext exr(sink);
        const exr_context_t c = exr.get();
        int part = 0;
        exr.check(exr_add_part(c, "", EXR_STORAGE_SCANLINE, &part));
        exr.check(exr_initialize_required_attr_simple(
            c, part, width, height, compression == ExrCompression::Zip ? EXR_COMPRESSION_ZIP : EXR_COMPRESSION_RLE));
        exr.check(exr_set_zip_compression_level(c, part, kZipLevel));
        for (const ExrChannel& ch : channels)
            exr.check(exr_add_channel(c, part, ch.name.c_str(), EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LINEAR, 1, 1));
        exr.check(exr_write_header(c));
        encode(exr, width, height, channels, compression);
        exr.finish();
    } catch (const std::exception& e) {
        throw RuntimeError(path + ": EXR encoding failed (" + e.what() + ")");
    }
    write_file_atomic(path, sink.bytes);
}

}  // namespace inkshade::io
