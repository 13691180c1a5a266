// A tar archive written one member at a time: POSIX ustar headers, a pax extended header
// (POSIX.1-2001) before a member whose name does not fit ustar's 100 + 155 bytes.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace inkshade::io {

// The bytes a member takes in a tar: its header(s), its data and the zero padding to 512.
// Every member is a regular file, mode 0644, owner 0, mtime 0: the same files give the same
// archive bytes.
std::string tar_member(std::string_view name, std::string_view data);

// The end of an archive: two zero blocks.
std::string_view tar_end();

// Appends members to a file. The caller adds tar_end() (TarWriter::finish) last.
class TarWriter {
public:
    // Opens `path` for writing, truncating it. Throws RuntimeError("PATH: reason").
    explicit TarWriter(const std::string& path);
    ~TarWriter();
    TarWriter(const TarWriter&) = delete;
    TarWriter& operator=(const TarWriter&) = delete;

    // Appends bytes as they are (tar_member's result, or a copy of another archive's members).
    void append(std::string_view bytes);
    // Writes the end blocks, flushes to the disk and closes. Throws RuntimeError.
    void finish();
    uint64_t bytes() const { return bytes_; }  // written so far
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::FILE* file_ = nullptr;
    uint64_t bytes_ = 0;
};

}  // namespace inkshade::io
