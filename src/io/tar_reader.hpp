// The members of a tar archive, read back: ustar headers (checksums checked) with pax 'x'
// extended headers' paths, as io/tar_writer.hpp writes them and tar tools write them.
#pragma once
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>

namespace inkshade::io {

struct TarMember {
    std::string name;
    uint64_t size = 0;
    uint64_t offset = 0;  // of the member's data in the archive
    uint64_t end = 0;     // offset after its data and padding: where the next header starts
};

class TarReader {
public:
    // Throws RuntimeError("PATH: reason") when the file cannot be opened.
    explicit TarReader(const std::string& path);

    // The next regular file, or nullopt at the end of the archive (two zero blocks, or the end
    // of the file right after a member). Throws RuntimeError("PATH: reason") for a bad header
    // checksum or a member that goes past the end of the file (a truncated archive).
    std::optional<TarMember> next();
    // A member's bytes. Throws RuntimeError.
    std::string read(const TarMember& member);

    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::ifstream in_;
    uint64_t size_ = 0, offset_ = 0;
};

}  // namespace inkshade::io
