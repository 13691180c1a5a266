// One read path for all readers: mmap (zero-copy, MAP_POPULATE so a 500 MB file faults in
// at once instead of page by page), falling back to pread() where mapping fails.
#include "io/file_bytes.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <memory>
#include <system_error>

#include "inkshade/error.hpp"

namespace inkshade::io {
namespace {

[[noreturn]] void fail_errno(const std::string& path, int err) {
    if (err == EISDIR) throw InputError(path, "is a directory");
    throw InputError(path, "cannot open file (" + std::generic_category().message(err) + ")");
}

}  // namespace

FileBytes::FileBytes(const std::string& path) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);  // a FIFO must not block the open
    if (fd < 0) fail_errno(path, errno);
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};

    struct stat st {};
    if (::fstat(fd, &st) != 0) fail_errno(path, errno);
    if (S_ISDIR(st.st_mode)) throw InputError(path, "is a directory");

    // Devices and pipes could stream forever (a link named x.stl to /dev/zero): refuse them.
    if (!S_ISREG(st.st_mode)) throw InputError(path, "not a regular file");
    if (st.st_size == 0) throw InputError(path, "empty file");
    size_ = size_t(st.st_size);
#ifndef INKSHADE_FUZZ  // fuzz builds read into an exact-size block: AddressSanitizer then sees
                       // a read past the end, which a page-padded mapping would hide
    void* p = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (p != MAP_FAILED) {
        data_ = static_cast<const char*>(p);
        mapped_ = true;
        return;
    }
#endif
    // Not mappable (some network or FUSE file systems): read it instead.
    std::unique_ptr<char[]> owned(new char[size_]);
    for (size_t done = 0; done < size_;) {
        ssize_t n = ::pread(fd, owned.get() + done, size_ - done, off_t(done));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail_errno(path, errno);
        if (n == 0) {  // shrank since fstat
            size_ = done;
            break;
        }
        done += size_t(n);
    }
    if (size_ == 0) throw InputError(path, "empty file");
    data_ = owned.release();
}

FileBytes::~FileBytes() {
    if (mapped_)
        ::munmap(const_cast<char*>(data_), size_);
    else
        delete[] data_;
}

}  // namespace inkshade::io
