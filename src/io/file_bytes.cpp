// One read path for all readers: mmap (zero-copy, MAP_POPULATE so a 500 MB file faults in
// once instead of page by page), falling back to read() for pipes and special files.
#include "io/file_bytes.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <memory>
#include <system_error>
#include <vector>

#include "inkshade/error.hpp"

namespace inkshade::io {
namespace {

[[noreturn]] void fail_errno(const std::string& path, int err) {
    if (err == EISDIR) throw InputError(path, "is a directory");
    throw InputError(path, "cannot open file (" + std::generic_category().message(err) + ")");
}

}  // namespace

FileBytes::FileBytes(const std::string& path) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) fail_errno(path, errno);
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};

    struct stat st {};
    if (::fstat(fd, &st) != 0) fail_errno(path, errno);
    if (S_ISDIR(st.st_mode)) throw InputError(path, "is a directory");

    if (S_ISREG(st.st_mode)) {
        if (st.st_size == 0) throw InputError(path, "empty file");
        size_ = size_t(st.st_size);
        void* p = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
        if (p != MAP_FAILED) {
            data_ = static_cast<const char*>(p);
            mapped_ = true;
            return;
        }
    }
    // Not mappable (pipe, /dev/stdin, exotic file system): read until end of file.
    std::vector<char> bytes;
    char chunk[1 << 16];
    for (;;) {
        ssize_t n = ::read(fd, chunk, sizeof chunk);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail_errno(path, errno);
        if (n == 0) break;
        bytes.insert(bytes.end(), chunk, chunk + n);
    }
    if (bytes.empty()) throw InputError(path, "empty file");
    char* owned = new char[bytes.size()];
    std::copy(bytes.begin(), bytes.end(), owned);
    data_ = owned;
    size_ = bytes.size();
}

FileBytes::~FileBytes() {
    if (mapped_)
        ::munmap(const_cast<char*>(data_), size_);
    else
        delete[] data_;
}

}  // namespace inkshade::io
