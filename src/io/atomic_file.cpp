#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "inkshade/error.hpp"

namespace inkshade::io {

void write_file_atomic(const std::string& path, std::string_view bytes) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    std::error_code ec;
    if (fs::is_directory(target, ec)) throw RuntimeError(path + ": is a directory");
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    // mkstemp gives a unique name in the same directory (rename is atomic only within one
    // file system).
    std::string tmpl = (dir / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
    int fd = mkstemp(tmpl.data());
    if (fd < 0) throw RuntimeError(path + ": cannot create file (" + std::strerror(errno) + ")");
    auto fail = [&](const char* what) {
        int err = errno;
        ::close(fd);
        ::unlink(tmpl.c_str());
        throw RuntimeError(path + ": " + what + " (" + std::strerror(err) + ")");
    };
    size_t done = 0;
    while (done < bytes.size()) {
        ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("cannot write file");
        }
        done += size_t(n);
    }
    if (::fchmod(fd, 0644) != 0) fail("cannot set permissions");
    if (::close(fd) != 0) {
        int err = errno;
        ::unlink(tmpl.c_str());
        throw RuntimeError(path + ": cannot write file (" + std::strerror(err) + ")");
    }
    if (std::rename(tmpl.c_str(), path.c_str()) != 0) {
        int err = errno;
        ::unlink(tmpl.c_str());
        throw RuntimeError(path + ": cannot write file (" + std::strerror(err) + ")");
    }
}

}  // namespace inkshade::io
