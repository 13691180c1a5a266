// Wavefront OBJ through tinyobjloader (MTL Kd colours and map_Kd textures, relative indices,
// triangulation).
// tinyobj is lenient by design: it reads garbage as zeros, skips faces with bad indices, can be
// made to allocate per `t` line and converts `vw` weights unchecked, so a strict pre-scan of our
// own runs first, on the lines tinyobj sees (a lone '\r' ends a line for both). It rejects
// binary data, non-numeric and non-finite values and out-of-range indices with a line number,
// and records each polygon's corner count; `t` and `vw` lines are dropped. tinyobj then only
// sees text it handles well, and its results are still checked against the attribute counts.
#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <istream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <streambuf>
#include <string>
#include <vector>

#include <tiny_obj_loader.h>

#include "inkshade/error.hpp"
#include "io/file_bytes.hpp"
#include "io/readers.hpp"
#include "io/text_scanner.hpp"
#include "io/texture_image.hpp"

namespace inkshade::io {
namespace {

// tinyobj's ear clipping costs O(n^3) in the worst case per n-gon: files with larger polygons
// are fan-triangulated here instead, so no input can make loading crawl.
constexpr uint32_t kMaxEarClippedCorners = 16;

struct Prescan {
    size_t positions = 0, texcoords = 0, normals = 0;
    std::vector<uint32_t> corners;  // per face with >= 3 corners, in file order
    uint32_t max_corners = 0;
    bool has_dropped = false;          // `t` or `vw` lines, which are removed before tinyobj sees them
    std::vector<std::string> mtllibs;  // as named on `mtllib` lines, for finding their textures
};

// Checks one "v/vt/vn" corner. Negative indices count back from the elements read so far;
// positive ones may point forward, so they are checked against the final count afterwards.
struct IndexCheck {
    int64_t max_positive = 0;
    size_t line = 0;
};

Prescan prescan(std::string_view text, const std::string& path) {
    for (size_t i = 0; i < text.size(); ++i) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        if (c < 0x20 && c != '\n' && c != '\r' && c != '\t')
            throw InputError(path, "not a text OBJ file (binary byte at offset " + std::to_string(i) + ")");
    }
    Prescan s;
    IndexCheck max_ref[3];  // v, vt, vn
    TextScanner in(text, path, 1, '#');
    auto check_corner = [&](std::string_view tok) {
        std::string_view parts[3];
        size_t n = 0;
        for (size_t start = 0;; ++n) {
            size_t slash = tok.find('/', start);
            if (n == 3) in.fail("too many '/' in face corner " + quote_token(tok));
            parts[n] = tok.substr(start, slash == std::string_view::npos ? slash : slash - start);
            if (slash == std::string_view::npos) break;
            start = slash + 1;
        }
        const size_t counts[3] = {s.positions, s.texcoords, s.normals};
        static const char* what[3] = {"vertex", "texture coordinate", "normal"};
        for (size_t k = 0; k <= n; ++k) {
            if (parts[k].empty() && k == 1 && n == 2) continue;  // "1//3"
            int64_t idx = 0;
            if (!parse_number(parts[k], idx) || idx == 0)
                in.fail("bad face index " + quote_token(tok) + " (indices are non-zero integers)");
            if (idx < 0 && 0 - uint64_t(idx) > counts[k])  // unsigned negation: INT64_MIN is valid input
                in.fail(std::string("face refers to ") + what[k] + " " + std::to_string(idx) + " but only " +
                        std::to_string(counts[k]) + " are defined before it");
            if (idx > max_ref[k].max_positive) max_ref[k] = {idx, in.line()};
        }
    };
    auto rest_numbers = [&](const char* what) {  // optional trailing values must still be numbers
        while (!in.at_line_end()) in.number<float>(what);
    };
    while (!in.at_end()) {
        std::string_view key = in.token_on_line();
        if (key == "v") {
            for (int k = 0; k < 3; ++k) {
                float x = in.number_on_line<float>("a vertex coordinate");
                if (!std::isfinite(x))
                    in.fail("vertex " + std::to_string(s.positions) + " has a non-finite coordinate");
            }
            rest_numbers("a vertex weight or colour");
            ++s.positions;
        } else if (key == "vn") {
            for (int k = 0; k < 3; ++k) in.number_on_line<float>("a normal coordinate");
            ++s.normals;
        } else if (key == "vt") {
            in.number_on_line<float>("a texture coordinate");
            rest_numbers("a texture coordinate");
            ++s.texcoords;
        } else if (key == "f" || key == "l" || key == "p") {
            uint32_t n = 0;
            for (std::string_view tok = in.token_on_line(); !tok.empty(); tok = in.token_on_line(), ++n)
                check_corner(tok);
            if (key == "f" && n >= 3) {
                s.corners.push_back(n);
                s.max_corners = std::max(s.max_corners, n);
            }
        } else if (key == "t" || key == "vw") {
            s.has_dropped = true;
        } else if (key == "mtllib") {
            // tinyobj reads a library line by line with no size limit: a device (or a link to
            // one) would never end, so only regular files may be named.
            for (std::string_view name = in.token_on_line(); !name.empty(); name = in.token_on_line()) {
                std::error_code ec;
                auto lib = std::filesystem::path(path).parent_path() / std::string(name);
                if (std::filesystem::exists(lib, ec) && !std::filesystem::is_regular_file(lib, ec))
                    in.fail("material library " + quote_token(name) + " is not a regular file");
                s.mtllibs.emplace_back(name);
            }
        }
        in.skip_line();
    }
    const size_t counts[3] = {s.positions, s.texcoords, s.normals};
    static const char* what[3] = {"vertex", "texture coordinate", "normal"};
    for (int k = 0; k < 3; ++k)
        if (uint64_t(max_ref[k].max_positive) > counts[k])
            throw InputError(path, std::string("face refers to ") + what[k] + " " +
                                       std::to_string(max_ref[k].max_positive) + " but the file has only " +
                                       std::to_string(counts[k]) + " at line " + std::to_string(max_ref[k].line));
    if (s.positions > std::numeric_limits<int>::max() / 3) throw InputError(path, "too many vertices for an OBJ file");
    return s;
}

// What line sets select OBJ faces by (docs/inputs.md): the object of a face is the name of the
// last `o` or `g` statement before it (tinyobj starts a shape at each), its face mark its
// smoothing group (`s N`; `s off` and `s 0` unmarked; groups past 255 are mark 255).
struct ObjFaceLabels {
    bool objects = false, marks = false;  // any named shape; any face in a smoothing group
};

ObjFaceLabels obj_face_labels(const std::vector<tinyobj::shape_t>& shapes) {
    ObjFaceLabels labels;
    for (const tinyobj::shape_t& shape : shapes) {
        labels.objects |= !shape.name.empty();
        for (unsigned g : shape.mesh.smoothing_group_ids) labels.marks |= g != 0;
    }
    return labels;
}

// The index of `name` in `names`, appended when new (shapes of one name are one object).
uint32_t object_index(std::vector<std::string>& names, const std::string& name) {
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return uint32_t(i);
    names.push_back(name);
    return uint32_t(names.size() - 1);
}

uint8_t smoothing_mark(const tinyobj::shape_t& shape, size_t face) {
    const auto& groups = shape.mesh.smoothing_group_ids;
    return face < groups.size() ? uint8_t(std::min<unsigned>(groups[face], 255)) : 0;
}

// Read-only istream over the mapped file, so tinyobj parses without another copy.
struct MemoryBuffer : std::streambuf {
    MemoryBuffer(const char* data, size_t size) {
        char* p = const_cast<char*>(data);  // get area only: never written
        setg(p, p, p + size);
    }
};

// tinyobj's number parser (tryParseDouble) overflows an int while reading an exponent of ten
// digits or more, such as 1e2147483648 (undefined behaviour; found by fuzzing). No real file
// holds one, so such a number in the OBJ or an MTL file is refused before tinyobj reads it.
// Lines tinyobj skips as comments ('#' first) are skipped; a line ends at '\n' or '\r' for
// both.
void check_exponents(std::string_view text, const std::string& path, const std::string& where) {
    auto digit = [](char c) { return c >= '0' && c <= '9'; };
    size_t line = 1;
    bool line_start = true;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n' || c == '\r') {
            line += c == '\n' || i + 1 == text.size() || text[i + 1] != '\n';
            line_start = true;
            continue;
        }
        if (line_start && c == '#') {
            while (i + 1 < text.size() && text[i + 1] != '\n' && text[i + 1] != '\r') ++i;
            continue;
        }
        if (c != ' ' && c != '\t') line_start = false;
        if ((c == 'e' || c == 'E') && i > 0 && (digit(text[i - 1]) || text[i - 1] == '.')) {
            size_t j = i + 1;
            if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
            const size_t first = j;
            while (j < text.size() && digit(text[j])) ++j;
            if (j - first >= 10)
                throw InputError(path, where + "number with a " + std::to_string(j - first) +
                                           "-digit exponent at line " + std::to_string(line));
        }
    }
}

// Material libraries for tinyobj, read through FileBytes (regular files only, like the OBJ) and
// checked by check_exponents before tinyobj's LoadMtl parses them. Names are relative to the
// OBJ's directory. A library that is missing or cannot be read is a warning, as in tinyobj.
class MtlReader : public tinyobj::MaterialReader {
public:
    MtlReader(std::string obj_path, std::string dir) : obj_path_(std::move(obj_path)), dir_(std::move(dir)) {}
    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warn, std::string* err) override {
        const std::string path = dir_.empty() ? name : dir_ + "/" + name;
        std::error_code ec;
        if (!std::filesystem::exists(path, ec) || std::filesystem::is_empty(path, ec)) {
            if (warn) *warn += "Material file [ " + name + " ] not found or empty.\n";
            return false;
        }
        std::optional<FileBytes> bytes;
        try {
            bytes.emplace(path);
        } catch (const InputError& e) {
            if (warn) *warn += std::string(e.what()) + "\n";
            return false;
        }
        check_exponents(bytes->view(), obj_path_, "material library " + quote_token(name) + ": ");
        MemoryBuffer buffer(bytes->data(), bytes->size());
        std::istream stream(&buffer);
        tinyobj::LoadMtl(names, materials, &stream, warn, err);
        return true;
    }

private:
    std::string obj_path_, dir_;
};

std::string first_line(const std::string& s) {
    std::string line = s.substr(0, s.find('\n'));
    return line.empty() ? "unknown error" : line;
}

// True when many positions repeat exactly: exporters that write each face's corners as
// fresh `v` lines produce this soup, which needs welding like STL.
bool positions_repeat(const std::vector<float>& v) {
    size_t n = v.size() / 3;
    if (n < 4) return false;
    std::vector<std::array<uint32_t, 3>> keys(n);
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            float x = v[3 * i + size_t(k)] + 0.0f;  // -0 == +0
            std::memcpy(&keys[i][size_t(k)], &x, 4);
        }
    std::sort(keys.begin(), keys.end());
    size_t repeats = 0;
    for (size_t i = 1; i < n; ++i) repeats += keys[i] == keys[i - 1];
    return repeats * 4 >= n;  // a quarter or more
}

// Lines tinyobj must not see, by its own test of a keyword (after spaces and tabs): `t` (tags:
// it allocates per claimed tag count) and `vw` (skin weights: it converts any number to an int
// joint id, undefined behaviour for 1e40). Inkshade uses neither.
bool dropped_line(std::string_view line) {
    const size_t b = line.find_first_not_of(" \t");
    if (b == std::string_view::npos) return false;
    auto blank = [&](size_t i) { return i < line.size() && (line[i] == ' ' || line[i] == '\t'); };
    return (line[b] == 't' && blank(b + 1)) || (line.substr(b, 2) == "vw" && blank(b + 2));
}

}  // namespace

Mesh read_obj(const std::string& path, bool& is_soup) {
    FileBytes file(path);
    std::string_view text = file.view();
    // tinyobj ends a line at '\r' too (old Mac files): a lone '\r' becomes '\n' first, so the
    // pre-scan sees the same lines as tinyobj (a face after "#...\r" would otherwise pass unchecked).
    std::string unix_text;
    for (size_t i = text.find('\r'); i != std::string_view::npos; i = text.find('\r', i + 1)) {
        if (i + 1 < text.size() && text[i + 1] == '\n') continue;
        if (unix_text.empty()) unix_text.assign(text);
        unix_text[i] = '\n';
    }
    if (!unix_text.empty()) text = unix_text;
    Prescan scan = prescan(text, path);
    check_exponents(text, path, "");

    std::string filtered;  // the text without dropped lines, only when it has any
    if (scan.has_dropped) {
        for (size_t pos = 0; pos < text.size();) {
            size_t nl = std::min(text.find('\n', pos), text.size());
            std::string_view line = text.substr(pos, nl - pos);
            if (!dropped_line(line)) filtered.append(line).push_back('\n');
            pos = nl + 1;
        }
        text = filtered;
    }

    MemoryBuffer buffer(text.data(), text.size());
    std::istream stream(&buffer);
    std::string dir = std::filesystem::path(path).parent_path().string();
    MtlReader mtl_reader(path, dir);
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    bool triangulate = scan.max_corners <= kMaxEarClippedCorners;
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &stream, &mtl_reader, triangulate,
                          /*default_vcols_fallback=*/false))
        throw InputError(path, first_line(err));
    if (warn.find("invalid vertex index") != std::string::npos || warn.find("out of bounds") != std::string::npos)
        throw InputError(path, first_line(warn));

    // Every corner must index existing attributes (the pre-scan makes this a safety net).
    const size_t nv = attrib.vertices.size() / 3, nt = attrib.texcoords.size() / 2, nn = attrib.normals.size() / 3;
    bool all_normals = nn > 0, all_uvs = nt > 0;
    size_t corner_total = 0, face_total = 0;
    for (const tinyobj::shape_t& shape : shapes) {
        face_total += shape.mesh.num_face_vertices.size();
        for (const tinyobj::index_t& c : shape.mesh.indices) {
            if (c.vertex_index < 0 || size_t(c.vertex_index) >= nv || c.normal_index >= int(nn) ||
                c.texcoord_index >= int(nt) || c.normal_index < -1 || c.texcoord_index < -1)
                throw InputError(path, "face refers to a vertex, normal or texture coordinate that does not exist");
            all_normals &= c.normal_index >= 0;
            all_uvs &= c.texcoord_index >= 0;
        }
        corner_total += shape.mesh.indices.size();
    }
    if (!triangulate) {  // polygons as written: tinyobj's per-face counts are 8-bit, use ours
        size_t sum = 0;
        for (uint32_t c : scan.corners) sum += c;
        bool same_face_count = face_total == scan.corners.size();
        if (sum != corner_total || !same_face_count)
            throw InputError(path, "face corner counts do not match the parsed faces");
    }

    Mesh mesh;
    bool colors = attrib.colors.size() == attrib.vertices.size() && nv > 0;
    // Vertex ids per corner: the position index when no per-corner attribute is kept, else
    // one vertex per distinct (v, vn, vt), found through a short chain per position.
    auto add_vertex = [&](const tinyobj::index_t& c) {
        size_t v = size_t(c.vertex_index);
        mesh.positions.emplace_back(attrib.vertices[3 * v], attrib.vertices[3 * v + 1], attrib.vertices[3 * v + 2]);
        if (colors) mesh.colors.emplace_back(attrib.colors[3 * v], attrib.colors[3 * v + 1], attrib.colors[3 * v + 2]);
        if (all_normals) {
            size_t n = size_t(c.normal_index);
            mesh.normals.emplace_back(attrib.normals[3 * n], attrib.normals[3 * n + 1], attrib.normals[3 * n + 2]);
        }
        if (all_uvs) {
            size_t t = size_t(c.texcoord_index);
            mesh.uvs.emplace_back(attrib.texcoords[2 * t], attrib.texcoords[2 * t + 1]);
        }
        return uint32_t(mesh.positions.size() - 1);
    };
    constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
    const bool keyed = all_normals || all_uvs;
    std::vector<uint32_t> first(keyed ? nv : 0, kNone), next;  // chains of vertices sharing a position
    std::vector<tinyobj::index_t> key;                         // the corner each vertex was made from
    if (!keyed)
        for (size_t v = 0; v < nv; ++v) add_vertex({int(v), -1, -1});
    auto vertex_of = [&](const tinyobj::index_t& c) -> uint32_t {
        if (!keyed) return uint32_t(c.vertex_index);
        uint32_t prev = kNone;
        for (uint32_t cur = first[size_t(c.vertex_index)]; cur != kNone; prev = cur, cur = next[cur]) {
            const tinyobj::index_t& k = key[cur];
            if ((!all_normals || k.normal_index == c.normal_index) &&
                (!all_uvs || k.texcoord_index == c.texcoord_index))
                return cur;
        }
        uint32_t id = add_vertex(c);
        key.push_back(c);
        next.push_back(kNone);
        (prev == kNone ? first[size_t(c.vertex_index)] : next[prev]) = id;
        return id;
    };

    // Materials: Kd per face; faces without `usemtl` get an appended default material.
    bool any_material = false;
    for (const tinyobj::shape_t& shape : shapes)
        for (int id : shape.mesh.material_ids) any_material |= id >= 0 && size_t(id) < materials.size();
    uint32_t default_material = kNone;
    if (any_material) {
        // map_Kd names are relative to the .mtl that holds them (tinyobj does not say which one
        // when there are several, so each library's directory is tried, then the OBJ's).
        std::vector<std::filesystem::path> texture_dirs;
        const std::filesystem::path obj_dir = dir.empty() ? std::filesystem::path(".") : std::filesystem::path(dir);
        for (const std::string& lib : scan.mtllibs) texture_dirs.push_back((obj_dir / lib).parent_path());
        texture_dirs.push_back(obj_dir);
        texture_dirs.erase(std::unique(texture_dirs.begin(), texture_dirs.end()), texture_dirs.end());
        std::map<std::string, std::shared_ptr<const Texture>> textures;  // each file decoded (or warned about) once
        for (const tinyobj::material_t& m : materials) {
            Material mat;
            mat.name = m.name;
            for (int k = 0; k < 3; ++k)
                if (std::isfinite(m.diffuse[k])) mat.diffuse[k] = std::clamp(float(m.diffuse[k]), 0.0f, 1.0f);
            if (!m.diffuse_texname.empty()) {
                auto [it, fresh] = textures.try_emplace(m.diffuse_texname);
                if (fresh) it->second = load_texture_or_warn(path, m.diffuse_texname, texture_dirs, mesh.warnings);
                mat.texture = it->second;
                // The texture is multiplied by Kd. MTL files that give only map_Kd mean the
                // texture as is (three.js and Blender read them so), but tinyobj fills the missing
                // Kd with 0.6 (its marker for this case); Kd 0 would hide the texture entirely.
                if (mat.texture && (mat.diffuse == glm::vec3(0.6f) || mat.diffuse == glm::vec3(0.0f)))
                    mat.diffuse = glm::vec3(1.0f);
            }
            mesh.materials.push_back(mat);
        }
    }

    mesh.triangles.reserve(triangulate ? face_total : corner_total);  // exact, or an upper bound
    const ObjFaceLabels labels = obj_face_labels(shapes);
    size_t face_index = 0;
    for (const tinyobj::shape_t& shape : shapes) {
        const auto& idx = shape.mesh.indices;
        const uint32_t object = labels.objects ? object_index(mesh.object_names, shape.name) : 0;
        size_t corner = 0;
        for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++face_index) {
            size_t n = triangulate ? shape.mesh.num_face_vertices[f] : scan.corners[face_index];
            if (n < 3 || corner + n > idx.size())
                throw InputError(path, "face corner counts do not match the parsed faces");
            uint32_t material = kNone;
            if (any_material) {
                int id = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
                if (id >= 0 && size_t(id) < materials.size()) {
                    material = uint32_t(id);
                } else {
                    if (default_material == kNone) {
                        default_material = uint32_t(mesh.materials.size());
                        mesh.materials.push_back(Material{"default"});
                    }
                    material = default_material;
                }
            }
            // Fan (tinyobj already gave triangles when it triangulated); vertices are numbered
            // in corner order, so evaluate them one statement at a time.
            uint32_t a = vertex_of(idx[corner]), b = vertex_of(idx[corner + 1]);
            for (size_t k = 2; k < n; ++k) {
                uint32_t c = vertex_of(idx[corner + k]);
                mesh.triangles.emplace_back(a, b, c);
                if (any_material) mesh.face_materials.push_back(material);
                if (labels.objects) mesh.face_objects.push_back(object);
                if (labels.marks) mesh.face_marks.push_back(smoothing_mark(shape, f));
                b = c;
            }
            corner += n;
        }
    }
    // `l` polylines: each pair of consecutive corners a loose segment, on the vertex a face
    // already made at that position when there is one (a line's corners carry no normal).
    for (const tinyobj::shape_t& shape : shapes) {
        const auto& idx = shape.lines.indices;
        size_t corner = 0;
        for (int count : shape.lines.num_line_vertices) {
            if (count < 0 || corner + size_t(count) > idx.size())
                throw InputError(path, "line corner counts do not match the parsed lines");
            uint32_t prev = kNone;
            for (size_t k = corner; k < corner + size_t(count); ++k) {
                const int v = idx[k].vertex_index;
                if (v < 0 || size_t(v) >= nv) throw InputError(path, "line refers to a vertex that does not exist");
                const uint32_t id = keyed && first[size_t(v)] != kNone
                                        ? first[size_t(v)]
                                        : vertex_of({v, all_normals ? 0 : -1, all_uvs ? 0 : -1});
                if (prev != kNone && prev != id) mesh.line_segments.emplace_back(prev, id);
                prev = id;
            }
            corner += size_t(count);
        }
    }
    is_soup = positions_repeat(attrib.vertices);
    return mesh;
}

Mesh read_obj(const std::string& path) {
    bool is_soup = false;
    return read_obj(path, is_soup);
}

}  // namespace inkshade::io
