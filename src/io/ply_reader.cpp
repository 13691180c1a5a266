// PLY (Turk 1994; Stanford scans): ascii, binary_little_endian and binary_big_endian. The
// whole file is in memory; one templated element walker serves all three encodings through a
// small value source (no virtual calls, no iostreams), so a 10 M-triangle binary file parses
// in well under a second. Element counts are checked against the bytes left before anything
// is allocated.
#include <algorithm>
#include <bit>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "inkshade/error.hpp"
#include "io/file_bytes.hpp"
#include "io/readers.hpp"
#include "io/text_scanner.hpp"
#include "io/texture_image.hpp"

namespace inkshade::io {
namespace {

enum class Scalar : uint8_t { I8, U8, I16, U16, I32, U32, F32, F64 };

size_t size_of(Scalar t) {
    constexpr size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
    return sizes[size_t(t)];
}
bool is_integer(Scalar t) { return t != Scalar::F32 && t != Scalar::F64; }

bool parse_scalar(std::string_view name, Scalar& t) {
    static constexpr std::pair<std::string_view, Scalar> names[] = {
        {"char", Scalar::I8},   {"int8", Scalar::I8},     {"uchar", Scalar::U8},   {"uint8", Scalar::U8},
        {"short", Scalar::I16}, {"int16", Scalar::I16},   {"ushort", Scalar::U16}, {"uint16", Scalar::U16},
        {"int", Scalar::I32},   {"int32", Scalar::I32},   {"uint", Scalar::U32},   {"uint32", Scalar::U32},
        {"float", Scalar::F32}, {"float32", Scalar::F32}, {"double", Scalar::F64}, {"float64", Scalar::F64}};
    for (auto [n, s] : names)
        if (n == name) return t = s, true;
    return false;
}

// Per-vertex attributes a property can feed; colours of integer type are scaled to [0,1].
enum Role : int { kSkip = -1, kX, kY, kZ, kNX, kNY, kNZ, kR, kG, kB, kU, kV, kRoleCount };

Role vertex_role(std::string_view n) {
    if (n == "x") return kX;
    if (n == "y") return kY;
    if (n == "z") return kZ;
    if (n == "nx") return kNX;
    if (n == "ny") return kNY;
    if (n == "nz") return kNZ;
    if (n == "red" || n == "r" || n == "diffuse_red") return kR;
    if (n == "green" || n == "g" || n == "diffuse_green") return kG;
    if (n == "blue" || n == "b" || n == "diffuse_blue") return kB;
    if (n == "u" || n == "s" || n == "texture_u" || n == "texture_s") return kU;
    if (n == "v" || n == "t" || n == "texture_v" || n == "texture_t") return kV;
    return kSkip;
}

struct Property {
    std::string name;
    Scalar type = Scalar::F32;  // item type for lists
    bool is_list = false;
    Scalar count_type = Scalar::U8;
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
    bool has_lists() const {
        for (const Property& p : properties)
            if (p.is_list) return true;
        return false;
    }
};

enum class Encoding { Ascii, LittleEndian, BigEndian };

struct Header {
    Encoding encoding = Encoding::Ascii;
    std::vector<Element> elements;
    size_t data_offset = 0;    // first byte after "end_header\n"
    size_t data_line = 0;      // line number of that byte (ascii)
    std::string texture_file;  // `comment TextureFile NAME` (MeshLab, Blender), relative to the file
    // Lines that start with no PLY keyword (Blender 2.4x writes "Created by Blender3D ..."
    // without `comment`): skipped, as assimp and Blender skip them, with one warning.
    size_t foreign_lines = 0;
    size_t first_foreign_line = 0;
    std::string first_foreign_text;
};

// The NAME of a `comment TextureFile NAME` line (the rest of the line, trimmed; may hold spaces).
std::string texture_file_of(std::string_view line) {
    constexpr std::string_view kKey = "TextureFile";
    size_t at = line.find(kKey);
    if (at == std::string_view::npos) return {};
    std::string_view rest = line.substr(at + kKey.size());
    if (rest.empty() || (rest[0] != ' ' && rest[0] != '\t')) return {};
    size_t b = rest.find_first_not_of(" \t"), e = rest.find_last_not_of(" \t\r");
    return b == std::string_view::npos ? std::string() : std::string(rest.substr(b, e - b + 1));
}

Header parse_header(std::string_view text, const std::string& path) {
    if (!(text.starts_with("ply\n") || text.starts_with("ply\r\n")))
        throw InputError(path, "not a PLY file (first line is not 'ply')");
    Header h;
    bool have_format = false;
    size_t pos = 0, line = 0;
    for (;;) {
        if (pos >= text.size()) throw InputError(path, "truncated PLY header (no end_header)");
        size_t nl = text.find('\n', pos);
        if (nl == std::string_view::npos) nl = text.size();
        const std::string_view raw = text.substr(pos, nl - pos);
        TextScanner in(raw, path, ++line);
        pos = nl + 1;
        std::string_view key = in.token();
        if (key == "comment" && in.token() == "TextureFile" && h.texture_file.empty())
            h.texture_file = texture_file_of(raw);
        if (line == 1 || key.empty() || key == "comment" || key == "obj_info") continue;
        if (key == "end_header") break;
        if (key == "format") {
            std::string_view f = in.token();
            if (f == "ascii")
                h.encoding = Encoding::Ascii;
            else if (f == "binary_little_endian")
                h.encoding = Encoding::LittleEndian;
            else if (f == "binary_big_endian")
                h.encoding = Encoding::BigEndian;
            else
                in.fail("unknown PLY format " + quote_token(f));
            have_format = true;
        } else if (key == "element") {
            Element e;
            e.name = std::string(in.token());
            if (e.name.empty()) in.fail("element without a name");
            e.count = in.number_on_line<uint64_t>("an element count");
            h.elements.push_back(std::move(e));
        } else if (key == "property") {
            if (h.elements.empty()) in.fail("property before any element");
            Property p;
            std::string_view type = in.token();
            if (type == "list") {
                p.is_list = true;
                std::string_view ct = in.token();
                if (!parse_scalar(ct, p.count_type)) in.fail("unknown PLY list count type " + quote_token(ct));
                if (!is_integer(p.count_type)) in.fail("PLY list count type must be an integer type");
                type = in.token();
            }
            if (!parse_scalar(type, p.type)) in.fail("unknown PLY property type " + quote_token(type));
            p.name = std::string(in.token());
            if (p.name.empty()) in.fail("property without a name");
            h.elements.back().properties.push_back(std::move(p));
        } else {
            // Not a keyword (a malformed keyword line failed above): skip the line.
            if (h.foreign_lines++ == 0) {
                h.first_foreign_line = line;
                std::string_view shown = raw;
                while (!shown.empty() && (shown.back() == '\r' || shown.back() == ' ' || shown.back() == '\t'))
                    shown.remove_suffix(1);
                h.first_foreign_text =
                    quote_token(shown.substr(std::min(shown.find_first_not_of(" \t"), shown.size())));
            }
        }
    }
    if (!have_format) throw InputError(path, "PLY header has no format line");
    h.data_offset = std::min(pos, text.size());
    h.data_line = line + 1;
    return h;
}

// --- value sources: one per encoding, same interface ------------------------------------

template <bool Swap>
class BinarySource {
public:
    BinarySource(std::string_view data, size_t offset, const std::string& path)
        : begin_(data.data()), p_(data.data() + offset), end_(data.data() + data.size()), path_(path) {}

    double scalar(Scalar t) {
        need(size_of(t));
        switch (t) {
            case Scalar::I8: return get<int8_t>();
            case Scalar::U8: return get<uint8_t>();
            case Scalar::I16: return get<int16_t>();
            case Scalar::U16: return get<uint16_t>();
            case Scalar::I32: return get<int32_t>();
            case Scalar::U32: return get<uint32_t>();
            case Scalar::F32: return get<float>();
            case Scalar::F64: return get<double>();
        }
        return 0;
    }
    // Integer-typed values (list counts, indices) are exact in a double.
    int64_t integer(Scalar t) { return int64_t(scalar(t)); }
    // Bytes a list of n items of type t needs; fails early so n cannot drive an allocation.
    void check_list(uint64_t n, Scalar t) {
        if (n > size_t(end_ - p_) / size_of(t))
            fail("list claims " + std::to_string(n) + " items but the file ends first (truncated?)");
    }
    void skip(Scalar t, uint64_t n = 1) {
        check_list(n, t);
        p_ += n * size_of(t);
    }
    size_t remaining() const { return size_t(end_ - p_); }
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& problem) const {
        throw InputError(path_, problem + " at byte " + std::to_string(p_ - begin_));
    }

private:
    void need(size_t n) {
        if (size_t(end_ - p_) < n) fail("unexpected end of file (truncated PLY data)");
    }
    template <class T>
    T get() {
        T v;
        if constexpr (Swap && sizeof(T) > 1) {
            using U =
                std::conditional_t<sizeof(T) == 2, uint16_t, std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>;
            U u;
            std::memcpy(&u, p_, sizeof u);
            if constexpr (sizeof(T) == 2)
                u = __builtin_bswap16(u);
            else if constexpr (sizeof(T) == 4)
                u = __builtin_bswap32(u);
            else
                u = __builtin_bswap64(u);
            std::memcpy(&v, &u, sizeof v);
        } else {
            std::memcpy(&v, p_, sizeof v);
        }
        p_ += sizeof(T);
        return v;
    }
    const char* begin_;
    const char* p_;
    const char* end_;
    const std::string& path_;
};

class AsciiSource {
public:
    AsciiSource(std::string_view data, size_t offset, size_t line, const std::string& path)
        : in_(data.substr(offset), path, line), path_(path) {}
    double scalar(Scalar) { return in_.number<double>("a PLY property value"); }
    int64_t integer(Scalar) { return in_.number<int64_t>("an integer (list count or index)"); }
    void check_list(uint64_t n, Scalar) {
        if (n > in_.remaining())
            fail("list claims " + std::to_string(n) + " items but the file ends first (truncated?)");
    }
    void skip(Scalar t, uint64_t n = 1) {
        check_list(n, t);
        for (uint64_t i = 0; i < n; ++i)
            if (in_.token().empty()) fail("unexpected end of file (truncated PLY data)");
    }
    size_t remaining() const { return in_.remaining(); }
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& problem) const { in_.fail(problem); }

private:
    TextScanner in_;
    const std::string& path_;
};

// --- element walker -----------------------------------------------------------------------

std::string plural(const Element& e) {
    if (e.name == "vertex") return "vertices";
    if (e.name == "face") return "faces";
    return "'" + e.name + "' elements";
}

bool is_face_list(const Property& p) { return p.name == "vertex_indices" || p.name == "vertex_index"; }

// A face's mark for line sets (docs/inputs.md): an integer property `facemark`, clamped to 0..255.
bool is_face_mark(const Property& p) { return p.name == "facemark" && !p.is_list && is_integer(p.type); }

template <class Source>
void read_elements(Source& src, const Header& h, bool binary, Mesh& mesh) {
    bool have_vertices = false;
    std::vector<uint32_t> polygon;
    for (const Element& e : h.elements) {
        if (e.properties.empty()) continue;  // no bytes at all, whatever its count claims
        // Smallest possible record: binary = sum of scalar and list-count sizes; ascii = one
        // character and one separator per property.
        size_t min_record = 0;
        for (const Property& p : e.properties) min_record += binary ? size_of(p.is_list ? p.count_type : p.type) : 2;
        if (e.count > (src.remaining() + (binary ? 0 : 1)) / min_record)
            throw InputError(src.path(), "header claims " + std::to_string(e.count) + " " + plural(e) +
                                             " but file has only " + std::to_string(src.remaining()) + " bytes");

        auto skip_property = [&](const Property& p) {
            if (p.is_list) {
                int64_t n = src.integer(p.count_type);
                if (n < 0) src.fail("negative list length " + std::to_string(n));
                src.skip(p.type, uint64_t(n));
            } else {
                src.skip(p.type);
            }
        };

        if (e.name == "vertex" && !have_vertices) {
            if (e.count > UINT32_MAX) src.fail("too many vertices (" + std::to_string(e.count) + ")");
            std::vector<Role> roles;
            std::vector<float> scale;
            bool seen[kRoleCount] = {};
            for (const Property& p : e.properties) {
                Role r = p.is_list ? kSkip : vertex_role(p.name);
                if (r != kSkip && seen[r]) r = kSkip;  // a repeated name: the first one wins
                if (r != kSkip) seen[r] = true;
                roles.push_back(r);
                bool colour = r == kR || r == kG || r == kB;
                float s = 1.0f;
                if (colour && p.type == Scalar::U16)
                    s = 1.0f / 65535.0f;
                else if (colour && p.type == Scalar::I16)
                    s = 1.0f / 32767.0f;
                else if (colour && p.type == Scalar::I8)
                    s = 1.0f / 127.0f;
                else if (colour && is_integer(p.type))
                    s = 1.0f / 255.0f;
                scale.push_back(s);
            }
            if (!seen[kX] || !seen[kY] || !seen[kZ]) src.fail("PLY vertex element lacks x, y or z");
            bool normals = seen[kNX] && seen[kNY] && seen[kNZ];
            bool colors = seen[kR] && seen[kG] && seen[kB];
            bool uvs = seen[kU] && seen[kV];
            size_t n = size_t(e.count);
            mesh.positions.resize(n);
            if (normals) mesh.normals.resize(n);
            if (colors) mesh.colors.resize(n);
            if (uvs) mesh.uvs.resize(n);
            float v[kRoleCount] = {};
            for (size_t i = 0; i < n; ++i) {
                for (size_t k = 0; k < roles.size(); ++k) {
                    if (roles[k] == kSkip)
                        skip_property(e.properties[k]);
                    else
                        v[roles[k]] = to_float(src.scalar(e.properties[k].type)) * scale[k];
                }
                if (!std::isfinite(v[kX]) || !std::isfinite(v[kY]) || !std::isfinite(v[kZ]))
                    src.fail("vertex " + std::to_string(i) + " has a non-finite coordinate");
                mesh.positions[i] = {v[kX], v[kY], v[kZ]};
                if (normals) mesh.normals[i] = {v[kNX], v[kNY], v[kNZ]};
                if (colors) mesh.colors[i] = {v[kR], v[kG], v[kB]};
                if (uvs) mesh.uvs[i] = {v[kU], v[kV]};
            }
            have_vertices = true;
        } else if (e.name == "face") {
            int list = -1;
            for (size_t k = 0; k < e.properties.size() && list < 0; ++k)
                if (is_face_list(e.properties[k])) list = int(k);
            if (list >= 0 && !e.properties[size_t(list)].is_list)
                src.fail("PLY face property '" + e.properties[size_t(list)].name + "' is not a list");
            if (list >= 0 && !is_integer(e.properties[size_t(list)].type))
                src.fail("PLY face indices must have an integer type");
            // Indices are checked as read when the vertices came first (the usual order);
            // otherwise load_mesh's validation catches them.
            int64_t limit = have_vertices ? int64_t(mesh.positions.size()) : int64_t(UINT32_MAX);
            mesh.triangles.reserve(mesh.triangles.size() + size_t(e.count));
            const bool marks = std::any_of(e.properties.begin(), e.properties.end(), is_face_mark);
            if (marks) mesh.face_marks.resize(mesh.triangles.size(), 0);
            for (uint64_t f = 0; f < e.count; ++f) {
                uint8_t mark = 0;
                for (size_t k = 0; k < e.properties.size(); ++k) {
                    const Property& p = e.properties[k];
                    if (marks && is_face_mark(p)) {
                        mark = uint8_t(std::clamp<int64_t>(src.integer(p.type), 0, 255));
                        continue;
                    }
                    if (int(k) != list) {
                        skip_property(p);
                        continue;
                    }
                    int64_t n = src.integer(p.count_type);
                    if (n < 0)
                        src.fail("face " + std::to_string(f) + " has negative vertex count " + std::to_string(n));
                    src.check_list(uint64_t(n), p.type);
                    polygon.clear();
                    for (int64_t j = 0; j < n; ++j) {
                        int64_t idx = src.integer(p.type);
                        if (idx < 0 || idx >= limit)
                            src.fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(idx) +
                                     " but there are only " + std::to_string(mesh.positions.size()) + " vertices");
                        polygon.push_back(uint32_t(idx));
                    }
                    // Fan triangulation; faces with fewer than 3 corners draw nothing.
                    for (size_t j = 1; j + 1 < polygon.size(); ++j)
                        mesh.triangles.emplace_back(polygon[0], polygon[j], polygon[j + 1]);
                }
                if (marks) mesh.face_marks.resize(mesh.triangles.size(), mark);  // the face's triangles
            }
        } else if (binary && !e.has_lists()) {
            src.skip(Scalar::U8, e.count * min_record);  // fixed-size records: one jump
        } else {
            for (uint64_t i = 0; i < e.count; ++i)
                for (const Property& p : e.properties) skip_property(p);
        }
    }
}

// One white material carrying the TextureFile texture, for every face. Without vertex texture
// coordinates the texture could not be placed: warn instead.
void attach_texture(Mesh& mesh, const std::string& name, const std::string& path) {
    if (mesh.uvs.empty()) {
        mesh.warnings.push_back(texture_warning(path, name, "the vertices have no texture coordinates"));
        return;
    }
    std::filesystem::path dir = std::filesystem::path(path).parent_path();
    auto texture = load_texture_or_warn(path, name, {dir.empty() ? std::filesystem::path(".") : dir}, mesh.warnings);
    if (!texture) return;
    mesh.materials.push_back(Material{"texture", glm::vec3(1.0f), std::move(texture)});
    mesh.face_materials.assign(mesh.triangles.size(), 0);
}

}  // namespace

Mesh read_ply(const std::string& path) {
    FileBytes file(path);
    Header h = parse_header(file.view(), path);
    Mesh mesh;
    if (h.foreign_lines > 0) {
        const bool one = h.foreign_lines == 1;
        mesh.warnings.push_back(path + ": skipped " + std::to_string(h.foreign_lines) + " header line" +
                                (one ? " that is" : "s that are") + " not PLY (" + (one ? "" : "first: ") + "line " +
                                std::to_string(h.first_foreign_line) + ": " + h.first_foreign_text + ")");
    }
    switch (h.encoding) {
        case Encoding::Ascii: {
            AsciiSource src(file.view(), h.data_offset, h.data_line, path);
            read_elements(src, h, false, mesh);
            break;
        }
        case Encoding::LittleEndian: {
            BinarySource<std::endian::native != std::endian::little> src(file.view(), h.data_offset, path);
            read_elements(src, h, true, mesh);
            break;
        }
        case Encoding::BigEndian: {
            BinarySource<std::endian::native != std::endian::big> src(file.view(), h.data_offset, path);
            read_elements(src, h, true, mesh);
            break;
        }
    }
    if (!h.texture_file.empty() && !mesh.triangles.empty()) attach_texture(mesh, h.texture_file, path);
    return mesh;
}

}  // namespace inkshade::io
