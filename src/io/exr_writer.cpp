// EXR through OpenEXR (Debian libopenexr-dev), encoded in memory so the file is written
// atomically like every other output.
#include "io/exr_writer.hpp"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfIO.h>

#include <algorithm>

#include "inkshade/error.hpp"
#include "io/atomic_file.hpp"

namespace inkshade::io {

namespace {

// The file's bytes in one string reserved for the raw pixels up front: Imf::StdOSStream's
// string stream grows by copies and is copied out again.
class StringStream final : public Imf::OStream {
public:
    explicit StringStream(size_t reserve) : Imf::OStream("memory") { bytes_.reserve(reserve); }
    void write(const char c[], int n) override {
        if (position_ + size_t(n) > bytes_.size()) bytes_.resize(position_ + size_t(n));
        std::copy(c, c + n, bytes_.begin() + std::ptrdiff_t(position_));
        position_ += size_t(n);
    }
    uint64_t tellp() override { return position_; }
    void seekp(uint64_t position) override { position_ = size_t(position); }
    std::string& bytes() { return bytes_; }

private:
    std::string bytes_;
    size_t position_ = 0;
};

}  // namespace

void write_exr(const std::string& path, int width, int height, const std::vector<ExrChannel>& channels,
               ExrCompression compression) {
    if (width <= 0 || height <= 0 || channels.empty()) throw RuntimeError(path + ": cannot write an empty EXR image");
    std::string bytes;
    try {
        Imf::Header header(width, height);
        header.compression() = compression == ExrCompression::Zip ? Imf::ZIP_COMPRESSION : Imf::RLE_COMPRESSION;
        // zlib's fastest level: on float fields (mantissa noise) level 1 is within a few percent
        // of the default's size at a fraction of its time (a dataset writes many of them).
        header.zipCompressionLevel() = 1;
        Imf::FrameBuffer frame;
        for (const ExrChannel& c : channels) {
            header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
            const size_t x_stride = sizeof(float) * c.stride;
            frame.insert(c.name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(c.data)), x_stride,
                                            x_stride * size_t(width)));
        }
        StringStream stream(size_t(width) * size_t(height) * sizeof(float) * channels.size() + 4096);
        {
            Imf::OutputFile file(stream, header);  // the file is complete once this is destroyed
            file.setFrameBuffer(frame);
            file.writePixels(height);
        }
        bytes = std::move(stream.bytes());
    } catch (const std::exception& e) {
        throw RuntimeError(path + ": EXR encoding failed (" + e.what() + ")");
    }
    write_file_atomic(path, bytes);
}

}  // namespace inkshade::io
