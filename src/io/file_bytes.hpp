// A whole input file in memory (memory-mapped when possible), opened with the one-line
// errors every reader shares: missing file, directory, empty file.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace inkshade::io {

class FileBytes {
public:
    // Throws InputError(path, "cannot open file (REASON)" | "is a directory" | "empty file").
    explicit FileBytes(const std::string& path);
    ~FileBytes();
    FileBytes(const FileBytes&) = delete;
    FileBytes& operator=(const FileBytes&) = delete;

    const char* data() const { return data_; }
    size_t size() const { return size_; }
    std::string_view view() const { return {data_, size_}; }

private:
    const char* data_ = nullptr;
    size_t size_ = 0;
    bool mapped_ = false;  // else data_ is owned by new[]
};

}  // namespace inkshade::io
