// STL, ASCII and binary. Returns a soup: three fresh vertices per facet (load_mesh welds it);
// facet normals are ignored because welding and angle-weighted normals replace them.
#include <bit>
#include <cstring>
#include <string>

#include "inkshade/error.hpp"
#include "io/file_bytes.hpp"
#include "io/readers.hpp"
#include "io/text_scanner.hpp"

namespace inkshade::io {
namespace {

static_assert(std::endian::native == std::endian::little, "binary STL reader assumes little endian");

constexpr size_t kHeaderBytes = 84;  // 80-byte header + uint32 facet count
constexpr size_t kRecordBytes = 50;  // normal, 3 vertices (12 floats) + uint16 attribute

bool iequals(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if ((a[i] | 0x20) != (b[i] | 0x20)) return false;
    return true;
}

Mesh read_binary(const FileBytes& file, const std::string& path) {
    if (file.size() < kHeaderBytes)
        throw InputError(
            path, "truncated binary STL: file has " + std::to_string(file.size()) + " bytes but the header needs 84");
    uint32_t count = 0;
    std::memcpy(&count, file.data() + 80, 4);
    size_t room = (file.size() - kHeaderBytes) / kRecordBytes;
    // Checked before allocating: a corrupt count must not reserve gigabytes.
    if (count > room)
        throw InputError(path, "header claims " + std::to_string(count) + " triangles but file has room for " +
                                   std::to_string(room));
    Mesh mesh;
    mesh.positions.resize(size_t(count) * 3);
    mesh.triangles.resize(count);
    const char* record = file.data() + kHeaderBytes;
    for (uint32_t t = 0; t < count; ++t, record += kRecordBytes) {
        std::memcpy(&mesh.positions[3 * size_t(t)], record + 12, 36);
        mesh.triangles[t] = glm::uvec3(3 * t, 3 * t + 1, 3 * t + 2);
    }
    return mesh;
}

Mesh read_ascii(const FileBytes& file, const std::string& path) {
    TextScanner in(file.view(), path);
    Mesh mesh;
    auto expect = [&](std::string_view keyword) {
        std::string_view tok = in.token();
        if (tok.empty())
            in.fail("unexpected end of file (truncated STL?) where '" + std::string(keyword) + "' was expected");
        if (!iequals(tok, keyword)) in.fail("expected '" + std::string(keyword) + "' but found " + quote_token(tok));
    };
    for (;;) {
        expect("solid");
        in.skip_line();  // the solid's name
        for (;;) {
            std::string_view tok = in.token();
            if (tok.empty()) in.fail("unexpected end of file (truncated STL?): missing 'endsolid'");
            if (iequals(tok, "endsolid")) break;
            if (!iequals(tok, "facet")) in.fail("expected 'facet' or 'endsolid' but found " + quote_token(tok));
            in.skip_line();  // "normal nx ny nz": recomputed after welding
            expect("outer");
            expect("loop");
            // Three vertices; a few exporters write polygons, which are fan-triangulated.
            uint32_t first = uint32_t(mesh.positions.size());
            for (;;) {
                tok = in.token();
                if (tok.empty()) in.fail("unexpected end of file (truncated STL?) inside a facet");
                if (iequals(tok, "endloop")) break;
                if (!iequals(tok, "vertex")) in.fail("expected 'vertex' or 'endloop' but found " + quote_token(tok));
                glm::vec3 p;
                for (int k = 0; k < 3; ++k) p[k] = in.number_on_line<float>("a vertex coordinate");
                if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                    in.fail("vertex " + std::to_string(mesh.positions.size()) + " has a non-finite coordinate");
                mesh.positions.push_back(p);
            }
            uint32_t n = uint32_t(mesh.positions.size()) - first;
            if (n < 3) in.fail("facet has " + std::to_string(n) + " vertices, at least 3 are needed");
            for (uint32_t k = 1; k + 1 < n; ++k) mesh.triangles.emplace_back(first, first + k, first + k + 1);
            expect("endfacet");
        }
        in.skip_line();                // "endsolid name"
        if (in.at_end()) return mesh;  // several solids may follow each other
    }
}

}  // namespace

Mesh read_stl(const std::string& path) {
    FileBytes file(path);
    std::string_view text = file.view();
    // Binary when the size matches the facet count exactly, whatever the header says: many
    // exporters start binary headers with "solid". Otherwise "solid" + text means ASCII.
    if (file.size() >= kHeaderBytes) {
        uint32_t count = 0;
        std::memcpy(&count, file.data() + 80, 4);
        if (file.size() == kHeaderBytes + kRecordBytes * uint64_t(count)) return read_binary(file, path);
    }
    size_t start = text.find_first_not_of(" \t\r\n");
    bool says_solid =
        start != std::string_view::npos && text.size() - start >= 5 && iequals(text.substr(start, 5), "solid");
    // A NUL or other control byte early on means a binary file with a "solid..." header
    // whose size does not match (trailing bytes, or truncated).
    bool looks_text = true;
    for (char c : text.substr(0, 1024))
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\r' && c != '\t') looks_text = false;
    if (says_solid && looks_text) return read_ascii(file, path);
    return read_binary(file, path);
}

}  // namespace inkshade::io
