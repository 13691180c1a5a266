// Reading tar members (io/tar_reader.hpp): ustar headers, pax 'x' paths, GNU 'L' long names.
#include "io/tar_reader.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "inkshade/error.hpp"

namespace inkshade::io {

namespace {

constexpr uint64_t kBlock = 512;

uint64_t padded(uint64_t n) { return (n + kBlock - 1) / kBlock * kBlock; }

bool parse_octal(const char* field, size_t width, uint64_t& value) {
    value = 0;
    size_t i = 0;
    while (i < width && field[i] == ' ') ++i;
    bool digits = false;
    for (; i < width && field[i] >= '0' && field[i] <= '7'; ++i, digits = true)
        value = value * 8 + uint64_t(field[i] - '0');
    return digits;
}

std::string field_text(const char* field, size_t width) { return std::string(field, strnlen(field, width)); }

// The "path" record of a pax extended header ("LEN path=VALUE\n" records), or "".
std::string pax_path(const std::string& records) {
    size_t at = 0;
    while (at < records.size()) {
        const size_t space = records.find(' ', at);
        if (space == std::string::npos) break;
        const size_t len = std::strtoull(records.c_str() + at, nullptr, 10);
        if (len == 0 || at + len > records.size()) break;
        const std::string record = records.substr(space + 1, at + len - space - 2);  // less the '\n'
        if (record.starts_with("path=")) return record.substr(5);
        at += len;
    }
    return "";
}

}  // namespace

TarReader::TarReader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    std::error_code ec;
    size_ = std::filesystem::file_size(path, ec);
    if (!in_ || ec) throw RuntimeError(path + ": cannot read file");
}

std::optional<TarMember> TarReader::next() {
    std::string long_name;
    while (true) {
        if (offset_ == size_) return std::nullopt;  // no end blocks: what a member left is the end
        if (offset_ + kBlock > size_) throw RuntimeError(path_ + ": truncated (a header is cut off)");
        char h[kBlock];
        in_.seekg(std::streamoff(offset_));
        if (!in_.read(h, kBlock)) throw RuntimeError(path_ + ": cannot read file");
        if (std::all_of(h, h + kBlock, [](char c) { return c == '\0'; })) return std::nullopt;
        uint64_t checksum = 0, size = 0;
        unsigned sum = 0;
        for (size_t i = 0; i < kBlock; ++i) sum += (i >= 148 && i < 156) ? ' ' : static_cast<unsigned char>(h[i]);
        if (!parse_octal(h + 148, 8, checksum) || checksum != sum)
            throw RuntimeError(path_ + ": bad header checksum at byte " + std::to_string(offset_));
        if (!parse_octal(h + 124, 12, size))
            throw RuntimeError(path_ + ": bad member size at byte " + std::to_string(offset_));
        TarMember m;
        m.offset = offset_ + kBlock;
        m.size = size;
        m.end = m.offset + padded(size);
        if (m.offset + size > size_) {
            const std::string name = field_text(h, 100);
            throw RuntimeError(path_ + ": truncated (" + (long_name.empty() ? name : long_name) + " needs " +
                               std::to_string(size) + " bytes, " + std::to_string(size_ - m.offset) + " left)");
        }
        offset_ = std::min(m.end, size_);
        const char type = h[156];
        if (type == 'x' || type == 'L') {  // the next member's name: pax path or GNU long name
            std::string data = read(m);
            long_name = type == 'x' ? pax_path(data) : field_text(data.data(), data.size());
            continue;
        }
        if (type != '0' && type != '\0' && type != '7') {  // directories, links, global headers
            long_name.clear();
            continue;
        }
        const std::string prefix = field_text(h + 345, 155);
        m.name = !long_name.empty() ? long_name : (prefix.empty() ? "" : prefix + "/") + field_text(h, 100);
        return m;
    }
}

std::string TarReader::read(const TarMember& member) {
    std::string data(member.size, '\0');
    in_.clear();
    in_.seekg(std::streamoff(member.offset));
    if (!in_.read(data.data(), std::streamsize(member.size))) throw RuntimeError(path_ + ": cannot read file");
    return data;
}

}  // namespace inkshade::io
