// Output files checked by their format's structure (batch/output_check.hpp).
#include "batch/output_check.hpp"

#include <cctype>
#include <cstdint>
#include <cstring>

#include <nlohmann/json.hpp>

namespace inkshade::batch {

namespace {

uint32_t big_endian32(const unsigned char* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
}

template <typename T>
T little_endian(std::string_view bytes, size_t at) {
    T v = 0;
    for (size_t i = sizeof(T); i-- > 0;) v = T(v << 8) | T(static_cast<unsigned char>(bytes[at + i]));
    return v;
}

// PNG (ISO/IEC 15948 5.2, 5.3): the signature, then chunks (length, type, data, CRC) up to IEND.
std::string png_problem(std::string_view b) {
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (b.size() < 8 || std::memcmp(b.data(), signature, 8) != 0) return "not a PNG (no PNG signature)";
    for (size_t at = 8; at + 12 <= b.size();) {
        const auto* p = reinterpret_cast<const unsigned char*>(b.data() + at);
        const uint64_t length = big_endian32(p);
        if (std::memcmp(p + 4, "IEND", 4) == 0) return "";
        at += 12 + length;
    }
    return "truncated PNG (no IEND chunk)";
}

// Scan lines per chunk of each OpenEXR compression (OpenEXR file layout, "compression").
int exr_lines_per_chunk(unsigned compression) {
    static const int lines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
    return compression < sizeof lines / sizeof lines[0] ? lines[compression] : 0;
}

// OpenEXR ("Technical Introduction", file layout): magic, version, attributes up to an empty
// name, then for a single-part scan-line image one 64-bit offset per chunk; each chunk is its
// y, its data size and the data.
std::string exr_problem(std::string_view b) {
    if (b.size() < 8 || little_endian<uint32_t>(b, 0) != 20000630u) return "not an OpenEXR file (no magic number)";
    const uint32_t flags = little_endian<uint32_t>(b, 4);
    if (flags & (0x200 | 0x800 | 0x1000)) return "";  // tiled, deep or multi-part: the magic only
    int32_t y_min = 0, y_max = -1;
    int lines = 0;
    size_t at = 8;
    while (true) {
        const size_t name_end = b.find('\0', at);
        if (name_end == std::string_view::npos) return "truncated OpenEXR file (header)";
        if (name_end == at) break;
        const size_t type_end = b.find('\0', name_end + 1);
        if (type_end == std::string_view::npos || type_end + 5 > b.size()) return "truncated OpenEXR file (header)";
        const std::string_view name = b.substr(at, name_end - at);
        const uint32_t size = little_endian<uint32_t>(b, type_end + 1);
        const size_t value = type_end + 5;
        if (value + size > b.size()) return "truncated OpenEXR file (header)";
        if (name == "dataWindow" && size == 16) {
            y_min = int32_t(little_endian<uint32_t>(b, value + 4));
            y_max = int32_t(little_endian<uint32_t>(b, value + 12));
        }
        if (name == "compression" && size == 1) lines = exr_lines_per_chunk(static_cast<unsigned char>(b[value]));
        at = value + size;
    }
    if (lines == 0 || y_max < y_min) return "bad OpenEXR header (compression or data window)";
    const uint64_t chunks = (uint64_t(int64_t(y_max) - y_min) + uint64_t(lines)) / uint64_t(lines);
    const size_t table = at + 1;
    if (table + chunks * 8 > b.size()) return "truncated OpenEXR file (offset table)";
    for (uint64_t c = 0; c < chunks; ++c) {
        const uint64_t offset = little_endian<uint64_t>(b, table + c * 8);
        if (offset + 8 > b.size() || offset + 8 + little_endian<uint32_t>(b, offset + 4) > b.size())
            return "truncated OpenEXR file (scan-line chunk " + std::to_string(c) + " past the end)";
    }
    return "";
}

std::string svg_problem(std::string_view b) {
    size_t end = b.size();
    while (end > 0 && std::isspace(static_cast<unsigned char>(b[end - 1]))) --end;
    if (b.find("<svg") == std::string_view::npos) return "not an SVG file (no <svg> element)";
    if (!b.substr(0, end).ends_with("</svg>")) return "truncated SVG file (no closing </svg>)";
    return "";
}

}  // namespace

std::string output_problem(const std::string& name, std::string_view bytes) {
    if (name.ends_with(".png")) return png_problem(bytes);
    if (name.ends_with(".exr")) return exr_problem(bytes);
    if (name.ends_with(".svg")) return svg_problem(bytes);
    if (name.ends_with(".json")) {
        if (nlohmann::json::accept(bytes)) return "";
        return bytes.empty() ? "empty JSON file" : "JSON does not parse";
    }
    return "";
}

}  // namespace inkshade::batch
