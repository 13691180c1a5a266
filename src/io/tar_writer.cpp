// Tar members in the POSIX ustar format (POSIX.1-1988, IEEE Std 1003.1 "pax" section "ustar
// Interchange Format"), with a pax extended header ('x', POSIX.1-2001) for long names: what
// Python's tarfile, GNU tar and WebDataset read.
#include "io/tar_writer.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "inkshade/error.hpp"

namespace inkshade::io {

namespace {

constexpr size_t kBlock = 512;

// `value` in octal, zero-padded to width - 1 digits and a NUL, as ustar's numeric fields.
void octal(char* field, size_t width, uint64_t value) {
    for (size_t i = width - 1; i-- > 0; value >>= 3) field[i] = char('0' + (value & 7));
    field[width - 1] = '\0';
    if (value != 0) throw RuntimeError("tar: value too large for a " + std::to_string(width) + "-byte field");
}

// Splits `name` into ustar's prefix (<= 155 bytes) and name (<= 100) at a '/'; false when it
// cannot be.
bool split_ustar_name(std::string_view name, std::string_view& prefix, std::string_view& rest) {
    if (name.size() <= 100) {
        prefix = {};
        rest = name;
        return true;
    }
    for (size_t slash = name.find('/'); slash != std::string_view::npos; slash = name.find('/', slash + 1)) {
        if (slash <= 155 && name.size() - slash - 1 <= 100 && slash + 1 < name.size()) {
            prefix = name.substr(0, slash);
            rest = name.substr(slash + 1);
            return true;
        }
    }
    return false;
}

std::string header(std::string_view prefix, std::string_view name, uint64_t size, char type) {
    std::string h(kBlock, '\0');
    // copy, not memcpy: an empty view may hold a null pointer, which memcpy must not be given.
    std::copy_n(name.data(), std::min<size_t>(name.size(), 100), h.begin());
    octal(&h[100], 8, 0644);  // mode
    octal(&h[108], 8, 0);     // uid
    octal(&h[116], 8, 0);     // gid
    octal(&h[124], 12, size);
    octal(&h[136], 12, 0);  // mtime: fixed, so the archive's bytes depend on the files alone
    h[156] = type;
    std::memcpy(&h[257], "ustar", 6);  // magic "ustar\0", version "00"
    std::memcpy(&h[263], "00", 2);
    std::copy_n(prefix.data(), std::min<size_t>(prefix.size(), 155), h.begin() + 345);
    // The checksum: the sum of the header's bytes (unsigned) with the field itself as spaces.
    std::memset(&h[148], ' ', 8);
    unsigned sum = 0;
    for (char c : h) sum += static_cast<unsigned char>(c);
    octal(&h[148], 7, sum);  // six digits, NUL, and the space already there
    return h;
}

void pad(std::string& out) { out.append((kBlock - out.size() % kBlock) % kBlock, '\0'); }

// A pax record "LEN path=NAME\n", LEN counting its own digits.
std::string pax_record(std::string_view key, std::string_view value) {
    const size_t body = key.size() + value.size() + 3;  // ' ', '=', '\n'
    size_t len = body + 1;
    while (std::to_string(len).size() + body != len) ++len;
    return std::to_string(len) + " " + std::string(key) + "=" + std::string(value) + "\n";
}

}  // namespace

std::string tar_member(std::string_view name, std::string_view data) {
    std::string out;
    std::string_view prefix, rest;
    if (!split_ustar_name(name, prefix, rest)) {
        const std::string records = pax_record("path", name);
        out += header({}, "PaxHeader", records.size(), 'x');
        out += records;
        pad(out);
        prefix = {};
        rest = name.substr(name.size() > 100 ? name.size() - 100 : 0);  // for readers without pax
    }
    out += header(prefix, rest, data.size(), '0');
    out += data;
    pad(out);
    return out;
}

std::string_view tar_end() {
    static const std::string end(2 * kBlock, '\0');
    return end;
}

TarWriter::TarWriter(const std::string& path) : path_(path) {
    file_ = std::fopen(path.c_str(), "wb");
    if (!file_) throw RuntimeError(path + ": cannot create file (" + std::strerror(errno) + ")");
}

TarWriter::~TarWriter() {
    if (file_) std::fclose(file_);
}

void TarWriter::append(std::string_view bytes) {
    if (!file_) throw RuntimeError(path_ + ": archive already closed");
    if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) {
        // Back to the last whole member (a full disk): the archive stays readable.
        const int err = errno;
        std::clearerr(file_);
        std::fflush(file_);
        if (::ftruncate(::fileno(file_), off_t(bytes_)) == 0) std::fseek(file_, long(bytes_), SEEK_SET);
        throw RuntimeError(path_ + ": cannot write file (" + std::strerror(err) + ")");
    }
    bytes_ += bytes.size();
}

void TarWriter::finish() {
    append(tar_end());
    const bool ok = std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
    const int err = errno;
    const bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (!ok || !closed) throw RuntimeError(path_ + ": cannot write file (" + std::strerror(err) + ")");
}

}  // namespace inkshade::io
