// glTF 2.0 (.gltf with .bin files or data: URIs) and GLB (.glb; .vrm avatars are GLB) through
// tinygltf (Debian's header-only tiny_gltf.h, compiled here). tinygltf parses the JSON and loads
// buffers, but trusts accessor and bufferView sizes, so every byte range is checked here before
// it is read, and counts are bounded before anything is allocated from them. tinygltf gets no
// file system of its own: buffers come through callbacks that only read regular files, and
// images are decoded here (stb_image), so a bad texture is a warning, never a failure.
//
// What is read (section numbers are the glTF 2.0 specification's):
// - the default scene (or the first scene, or every root node when there is none), node
//   hierarchies with matrix or TRS transforms (3.5.2-3.5.3); normals by the inverse transpose,
//   and a mirroring transform flips the winding so front faces stay counter-clockwise (3.7.4);
// - TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN primitives (3.7.2.1); points and lines skipped;
// - POSITION, NORMAL, TEXCOORD_n, COLOR_0 in any component type the spec or
//   KHR_mesh_quantization allows, sparse accessors (3.6.2.3), accessors without a bufferView;
// - pbrMetallicRoughness baseColorFactor and baseColorTexture (3.9.2) with its KHR_texture_transform
//   (texture_transform.cpp), alphaMode, alphaCutoff
//   and doubleSided (3.9.4-3.9.5), KHR_materials_unlit, VRM 0.x and VRM 1.0 MToon parameters
//   and textures with an MToon material's emissive and normal map (vrm_materials.cpp);
// - the nodes' cameras (3.10) and KHR_lights_punctual lights (gltf_cameras_lights.cpp);
// - skins, morph targets, animations and VRM expressions, posed as LoadOptions::pose asks
//   (gltf_pose.cpp and the files it uses).
#include <fstream>  // tiny_gltf.h's writers use std::ofstream but include <fstream> only without TINYGLTF_NO_FS

#define TINYGLTF_IMPLEMENTATION  // compiled here, configured as everywhere (io/tiny_gltf_config.hpp)
#include "io/tiny_gltf_config.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/name_suggestion.hpp"
#include "inkshade/error.hpp"
#include "io/file_bytes.hpp"
#include "io/gltf_accessors.hpp"
#include "io/gltf_cameras_lights.hpp"
#include "io/gltf_pose_names.hpp"
#include "io/gltf_pose.hpp"
#include "io/readers.hpp"
#include "io/texture_image.hpp"
#include "io/texture_transform.hpp"
#include "io/vrm_materials.hpp"

namespace inkshade::io {
namespace {

// Bounds on what a file can make us allocate. Data-backed counts are also bounded by the
// buffer sizes; these catch instancing (one mesh under a million nodes) and accessors without
// a bufferView (zeros of any claimed count).
constexpr size_t kMaxVertices = size_t(1) << 28;
constexpr size_t kMaxTriangles = size_t(1) << 28;
constexpr size_t kMaxBufferFileBytes = size_t(4) << 30;  // GLB lengths are 32-bit anyway
constexpr size_t kMaxNodeDepth = 1024;
// tinygltf copies `extensions` and `extras` into its Value type recursively (and destroys them
// recursively): JSON nested 100000 deep overflowed the stack. glTF itself nests about 8 deep.
constexpr size_t kMaxJsonDepth = 512;
// Accessors without a bufferView are zeros (plus sparse values): no bytes back their count.
constexpr size_t kMaxDatalessElements = size_t(1) << 22;

// One-line, printable text from tinygltf's multi-line messages (which may quote file bytes).
std::string one_line(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '\n' || c == '\r') {
            if (!out.empty()) break;
            continue;
        }
        out += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
        if (out.size() > 200) {
            out += "...";
            break;
        }
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == '.')) out.pop_back();
    return out.empty() ? "unknown error" : out;
}

// tinygltf's wording made to read like the other readers' messages.
std::string explain_parse_error(const std::string& err) {
    std::string line = one_line(err);
    if (line.rfind("[json.exception.", 0) == 0) {  // nlohmann: "[json.exception.parse_error.101] parse error at ..."
        size_t close = line.find("] ");
        std::string what = close == std::string::npos ? line : line.substr(close + 2);
        return "bad JSON: " + what.substr(0, what.find("; last read:"));  // not the quoted file bytes
    }
    if (line.rfind("File not found : ", 0) == 0) return "buffer file '" + line.substr(17) + "' not found";
    if (line.rfind("File size mismatch : ", 0) == 0)
        return "buffer file size does not match its byteLength (" + line.substr(21) + ")";
    if (line.rfind("File read error : ", 0) == 0) return "cannot read buffer file " + line.substr(18);
    return line;
}

std::string percent_decode(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        auto hex = [](char c) {
            return std::isxdigit(static_cast<unsigned char>(c))
                       ? (std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : (std::tolower(c) - 'a' + 10))
                       : -1;
        };
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

// --- tinygltf callbacks -------------------------------------------------------------------

bool file_exists(const std::string& path, void*) {
    std::error_code ec;
    return std::filesystem::exists(path, ec);
}
std::string expand_path(const std::string& path, void*) { return path; }
bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    try {
        FileBytes bytes(path);  // refuses devices, FIFOs and directories
        if (bytes.size() > kMaxBufferFileBytes) {
            if (err) *err = "larger than 4 GiB";
            return false;
        }
        out->assign(bytes.data(), bytes.data() + bytes.size());
        return true;
    } catch (const InputError& e) {
        if (err) *err = one_line(e.what());
        return false;
    }
}
bool write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err = "writing is not supported";
    return false;
}

// Keeps the encoded bytes of data: URI images (tinygltf's own copy, safe to read). Images in a
// bufferView are not touched here: tinygltf hands over an unchecked pointer for those, so they
// are read later from the validated bufferView.
bool keep_encoded_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
    if (image->bufferView < 0 && bytes != nullptr && size > 0) image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// Refuses JSON nested deeper than kMaxJsonDepth (arrays and objects; brackets inside strings
// do not count) before tinygltf recurses through it.
void check_json_depth(std::string_view json, const std::string& path) {
    size_t depth = 0;
    bool in_string = false;
    for (size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (in_string) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth)
                throw InputError(path, "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels at byte " +
                                           std::to_string(i));
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
}

// --- GLB container (glTF 2.0 section 4.4) -------------------------------------------------

uint32_t le32(const char* p) {
    uint32_t v;
    std::memcpy(&v, p, 4);
    if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
    return v;
}

// Checks the header and chunk table so that the messages say what is wrong; returns the GLB's
// declared length (which may be less than the file).
size_t check_glb(std::string_view bytes, const std::string& path) {
    constexpr uint32_t kJson = 0x4E4F534A, kBin = 0x004E4942;
    if (bytes.size() < 12)
        throw InputError(path, "truncated GLB (" + std::to_string(bytes.size()) + " bytes; the header alone is 12)");
    if (bytes.substr(0, 4) != "glTF") {
        std::string magic;
        for (char c : bytes.substr(0, 4)) magic += (c >= 0x20 && c < 0x7f) ? c : '?';
        throw InputError(path, "not a GLB file (magic is '" + magic + "', expected 'glTF')");
    }
    const uint32_t version = le32(bytes.data() + 4), length = le32(bytes.data() + 8);
    if (version != 2)
        throw InputError(path, "GLB version " + std::to_string(version) + " is not supported (glTF 2.0 only)");
    if (length > bytes.size())
        throw InputError(path, "truncated GLB: the header says " + std::to_string(length) + " bytes but the file has " +
                                   std::to_string(bytes.size()));
    if (length < 20) throw InputError(path, "GLB has no JSON chunk");
    const uint32_t json_length = le32(bytes.data() + 12), json_type = le32(bytes.data() + 16);
    if (json_type != kJson) throw InputError(path, "the first GLB chunk is not JSON");
    if (uint64_t(json_length) + 20 > length)
        throw InputError(path,
                         "truncated GLB: the JSON chunk (" + std::to_string(json_length) + " bytes) runs past the end");
    const uint64_t bin_at = 20 + uint64_t(json_length);
    if (bin_at + 8 <= length) {
        const uint32_t bin_length = le32(bytes.data() + bin_at), bin_type = le32(bytes.data() + bin_at + 4);
        if (bin_type == kBin && bin_at + 8 + bin_length > length)
            throw InputError(
                path, "truncated GLB: the BIN chunk (" + std::to_string(bin_length) + " bytes) runs past the end");
    }
    return length;
}

// --- accessors (glTF 2.0 section 3.6) ----------------------------------------------------

int component_size(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

int component_count(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT4: return 16;  // a skin's inverseBindMatrices (no padding: 4-byte components)
        default: return 0;
    }
}

// One component as float. Normalized integers map to [0,1] or [-1,1] (section 3.11, the
// formulas KHR_mesh_quantization uses too).
float component(const unsigned char* p, int type, bool normalized) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float f;
            std::memcpy(&f, p, 4);
            return f;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? float(p[0]) / 255.0f : float(p[0]);
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            int8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? std::max(float(v) / 127.0f, -1.0f) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? float(v) / 65535.0f : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t v;
            std::memcpy(&v, p, 4);
            return float(v);
        }
        default: return 0.0f;
    }
}

uint32_t index_value(const unsigned char* p, int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, p, 2);
            return v;
        }
        default: {
            uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
    }
}

// Reads accessors of a loaded model, checking every range against the real buffer sizes.
class AccessorReader final : public GltfFloatReader {
public:
    AccessorReader(const tinygltf::Model& model, const std::string& path) : model_(model), path_(path) {}

    // A strided view of `count` elements of `element_bytes` starting `offset` bytes into
    // bufferView `view`; `what` names the accessor in errors.
    struct Span {
        const unsigned char* data = nullptr;
        size_t stride = 0;
    };
    Span span(int view, size_t offset, size_t count, size_t element_bytes, size_t component_bytes, bool strided,
              const std::string& what) const {
        if (view < 0 || size_t(view) >= model_.bufferViews.size())
            fail(what + " refers to bufferView " + std::to_string(view) + " but the file has " +
                 std::to_string(model_.bufferViews.size()));
        const tinygltf::BufferView& bv = model_.bufferViews[size_t(view)];
        const unsigned char* base = buffer_view_bytes(view, what);
        size_t stride = element_bytes;
        if (strided && bv.byteStride != 0) {
            // Section 3.6.2.4: 4..252, a multiple of the component size, at least one element.
            if (bv.byteStride < element_bytes || bv.byteStride > 252 || bv.byteStride % component_bytes != 0)
                fail(what + ": bufferView " + std::to_string(view) + " has byteStride " +
                     std::to_string(bv.byteStride) + " (elements are " + std::to_string(element_bytes) + " bytes)");
            stride = bv.byteStride;
        }
        if (count == 0) return {base, stride};
        {
            // offset + stride * (count - 1) + element_bytes <= byteLength, without overflow.
            const size_t length = bv.byteLength;
            bool fits = offset <= length && element_bytes <= length - offset &&
                        (count - 1) <= (length - offset - element_bytes) / stride;
            if (!fits)
                fail(what + ": " + std::to_string(count) + " elements of " + std::to_string(element_bytes) +
                     " bytes from offset " + std::to_string(offset) + " do not fit in bufferView " +
                     std::to_string(view) + " (" + std::to_string(length) + " bytes)");
        }
        return {base + offset, stride};
    }

    // The bytes of a bufferView, after checking it lies inside its buffer.
    const unsigned char* buffer_view_bytes(int view, const std::string& what) const {
        const tinygltf::BufferView& bv = model_.bufferViews[size_t(view)];
        if (bv.buffer < 0 || size_t(bv.buffer) >= model_.buffers.size())
            fail(what + ": bufferView " + std::to_string(view) + " refers to buffer " + std::to_string(bv.buffer) +
                 " but the file has " + std::to_string(model_.buffers.size()));
        const std::vector<unsigned char>& data = model_.buffers[size_t(bv.buffer)].data;
        if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
            fail(what + ": bufferView " + std::to_string(view) + " (bytes " + std::to_string(bv.byteOffset) + ".." +
                 std::to_string(bv.byteOffset + bv.byteLength) + ") is past the end of buffer " +
                 std::to_string(bv.buffer) + " (" + std::to_string(data.size()) + " bytes)");
        return data.data() + bv.byteOffset;
    }

    const tinygltf::Accessor& accessor(int index, const std::string& role) const {
        if (index < 0 || size_t(index) >= model_.accessors.size())
            fail(role + " refers to accessor " + std::to_string(index) + " but the file has " +
                 std::to_string(model_.accessors.size()));
        return model_.accessors[size_t(index)];
    }

    // Float components of accessor `index` (count x components, interleaving removed).
    // `allowed_counts` lists the accepted component counts (e.g. {3} for POSITION).
    std::vector<float> floats(int index, const std::string& role, std::initializer_list<int> allowed_counts,
                              int& components) const override {
        const tinygltf::Accessor& a = accessor(index, role);
        const std::string what = name(index, role);
        components = component_count(a.type);
        if (std::find(allowed_counts.begin(), allowed_counts.end(), components) == allowed_counts.end())
            fail(what + " has an unsupported element type");
        const int csize = component_size(a.componentType);
        if (csize == 0) fail(what + " has unknown componentType " + std::to_string(a.componentType));
        check_count(a, what);
        const size_t nc = size_t(components), esize = nc * size_t(csize);
        // The range is checked before the allocation: a count is only trusted once bytes back it.
        Span s =
            a.bufferView >= 0 ? span(a.bufferView, a.byteOffset, a.count, esize, size_t(csize), true, what) : Span{};
        std::vector<float> out(a.count * nc, 0.0f);  // no bufferView: zeros (section 3.6.2.1)
        if (s.data) {
            for (size_t i = 0; i < a.count; ++i)
                for (size_t k = 0; k < nc; ++k)
                    out[i * nc + k] =
                        component(s.data + i * s.stride + k * size_t(csize), a.componentType, a.normalized);
        }
        if (a.sparse.isSparse) {
            std::vector<uint32_t> at = sparse_indices(a, what);
            Span values = span(a.sparse.values.bufferView, size_t(std::max(0, a.sparse.values.byteOffset)), at.size(),
                               esize, size_t(csize), false, what + " sparse values");
            for (size_t j = 0; j < at.size(); ++j)
                for (size_t k = 0; k < nc; ++k)
                    out[size_t(at[j]) * nc + k] =
                        component(values.data + j * esize + k * size_t(csize), a.componentType, a.normalized);
        }
        for (size_t i = 0; i < out.size(); ++i)
            if (!std::isfinite(out[i])) fail(what + ": element " + std::to_string(i / nc) + " is not a finite number");
        return out;
    }

    // Vertex indices (section 3.7.2.1: SCALAR, unsigned byte/short/int), each checked against
    // `vertex_count`.
    std::vector<uint32_t> indices(int index, const std::string& role, size_t vertex_count) const {
        const tinygltf::Accessor& a = accessor(index, role);
        const std::string what = name(index, role);
        if (a.type != TINYGLTF_TYPE_SCALAR) fail(what + " is not SCALAR");
        if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(what + " has componentType " + std::to_string(a.componentType) +
                 " (indices must be unsigned byte, short or int)");
        check_count(a, what);
        const size_t csize = size_t(component_size(a.componentType));
        // Index bufferViews are tightly packed (section 3.6.2.4: byteStride only for vertex attributes).
        Span s = a.bufferView >= 0 ? span(a.bufferView, a.byteOffset, a.count, csize, csize, false, what) : Span{};
        std::vector<uint32_t> out(a.count, 0);
        if (s.data)
            for (size_t i = 0; i < a.count; ++i) out[i] = index_value(s.data + i * csize, a.componentType);
        if (a.sparse.isSparse) {
            std::vector<uint32_t> at = sparse_indices(a, what);
            Span values = span(a.sparse.values.bufferView, size_t(std::max(0, a.sparse.values.byteOffset)), at.size(),
                               csize, csize, false, what + " sparse values");
            for (size_t j = 0; j < at.size(); ++j) out[at[j]] = index_value(values.data + j * csize, a.componentType);
        }
        for (size_t i = 0; i < out.size(); ++i)
            if (out[i] >= vertex_count)
                fail(what + ": index " + std::to_string(i) + " is " + std::to_string(out[i]) +
                     " but the primitive has " + std::to_string(vertex_count) + " vertices");
        return out;
    }

    [[noreturn]] void fail(const std::string& problem) const override { throw InputError(path_, problem); }

private:
    static std::string name(int index, const std::string& role) {
        return "accessor " + std::to_string(index) + " (" + role + ")";
    }

    void check_count(const tinygltf::Accessor& a, const std::string& what) const {
        if (a.count > kMaxVertices * 3)
            fail(what + " claims " + std::to_string(a.count) + " elements (limit " + std::to_string(kMaxVertices * 3) +
                 ")");
        if (a.bufferView < 0 && a.count > kMaxDatalessElements)
            fail(what + " claims " + std::to_string(a.count) + " elements without a bufferView (limit " +
                 std::to_string(kMaxDatalessElements) + ")");
    }

    // Section 3.6.2.3: strictly increasing element indices, each below the accessor's count.
    std::vector<uint32_t> sparse_indices(const tinygltf::Accessor& a, const std::string& what) const {
        if (a.sparse.count < 0 || size_t(a.sparse.count) > a.count)
            fail(what + ": sparse count " + std::to_string(a.sparse.count) + " exceeds the accessor's " +
                 std::to_string(a.count));
        const int type = a.sparse.indices.componentType;
        if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(what + ": sparse indices have componentType " + std::to_string(type));
        const size_t csize = size_t(component_size(type)), n = size_t(a.sparse.count);
        Span s = span(a.sparse.indices.bufferView, size_t(std::max(0, a.sparse.indices.byteOffset)), n, csize, csize,
                      false, what + " sparse indices");
        std::vector<uint32_t> at(n);
        for (size_t j = 0; j < n; ++j) {
            at[j] = index_value(s.data + j * csize, type);
            if (at[j] >= a.count) fail(what + ": sparse index " + std::to_string(at[j]) + " is out of range");
        }
        return at;
    }

    const tinygltf::Model& model_;
    const std::string& path_;
};

// --- node transforms (glTF 2.0 section 3.5) ----------------------------------------------

glm::dmat4 local_transform(const tinygltf::Node& node, size_t index, const std::string& path) {
    auto bad = [&](const char* what) {
        throw InputError(path, "node " + std::to_string(index) + " has a bad " + what);
    };
    auto finite = [](const std::vector<double>& v) {
        return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
    };
    if (!node.matrix.empty()) {  // column-major, as glm (section 3.5.2)
        if (node.matrix.size() != 16 || !finite(node.matrix)) bad("matrix");
        return glm::make_mat4(node.matrix.data());
    }
    glm::dmat4 m(1.0);
    if (!node.translation.empty()) {
        if (node.translation.size() != 3 || !finite(node.translation)) bad("translation");
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    }
    if (!node.rotation.empty()) {  // unit quaternion (x, y, z, w)
        if (node.rotation.size() != 4 || !finite(node.rotation)) bad("rotation");
        glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        double len = glm::length(q);
        if (len > 0.0) m *= glm::mat4_cast(q / len);
    }
    if (!node.scale.empty()) {
        if (node.scale.size() != 3 || !finite(node.scale)) bad("scale");
        m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    }
    return m;  // T * R * S
}

struct Instance {
    int node;
    int mesh;
    glm::dmat4 transform;
};

// What the scene's nodes hold, in depth-first order.
struct SceneNodes {
    std::vector<Instance> meshes;
    std::vector<PlacedNode> cameras_and_lights;  // nodes with a camera or a KHR_lights_punctual light
};

// Every mesh instance of the scene with its world transform, and the nodes that may carry a
// camera or a light. The hierarchy must be a tree (section 3.5.3): a node reached twice (a
// cycle or two parents) is an error, never a hang.
SceneNodes scene_nodes(const tinygltf::Model& model, const std::string& path, const GltfPose& pose) {
    std::vector<int> roots;
    const int scene = model.defaultScene >= 0 ? model.defaultScene : (model.scenes.empty() ? -1 : 0);
    if (scene >= 0) {
        if (size_t(scene) >= model.scenes.size())
            throw InputError(path, "default scene " + std::to_string(scene) + " does not exist (the file has " +
                                       std::to_string(model.scenes.size()) + ")");
        roots = model.scenes[size_t(scene)].nodes;
    } else {  // no scene: every node that is nobody's child
        std::vector<char> is_child(model.nodes.size(), 0);
        for (const tinygltf::Node& n : model.nodes)
            for (int c : n.children)
                if (c >= 0 && size_t(c) < model.nodes.size()) is_child[size_t(c)] = 1;
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (!is_child[i]) roots.push_back(int(i));
    }
    SceneNodes out;
    std::vector<char> visited(model.nodes.size(), 0);
    struct Item {
        int node;
        glm::dmat4 parent;
        size_t depth;
    };
    std::vector<Item> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::dmat4(1.0), 0});
    while (!stack.empty()) {
        Item item = stack.back();
        stack.pop_back();
        if (item.node < 0 || size_t(item.node) >= model.nodes.size())
            throw InputError(path, "scene refers to node " + std::to_string(item.node) + " but the file has " +
                                       std::to_string(model.nodes.size()));
        if (visited[size_t(item.node)]++)
            throw InputError(
                path, "node " + std::to_string(item.node) + " is reached twice (the node hierarchy must be a tree)");
        if (item.depth > kMaxNodeDepth)
            throw InputError(path, "node hierarchy deeper than " + std::to_string(kMaxNodeDepth));
        const tinygltf::Node& node = model.nodes[size_t(item.node)];
        const glm::dmat4 world = item.parent * pose.local(size_t(item.node));
        if (node.mesh >= 0) {
            if (size_t(node.mesh) >= model.meshes.size())
                throw InputError(path, "node " + std::to_string(item.node) + " refers to mesh " +
                                           std::to_string(node.mesh) + " but the file has " +
                                           std::to_string(model.meshes.size()));
            // A skinned mesh ignores its node's transform (section 3.7.3.3): its joints place it
            // (GltfPose::deform).
            out.meshes.push_back({item.node, node.mesh, node.skin >= 0 ? glm::dmat4(1.0) : world});
        }
        if (node.camera >= 0 || node.extensions.count("KHR_lights_punctual"))
            out.cameras_and_lights.push_back({item.node, world});
        for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
            stack.push_back({*c, world, item.depth + 1});
    }
    return out;
}

// --- materials (section 3.9) and VRM MToon ------------------------------------------------

// glTF alphaMode, alphaCutoff, doubleSided and baseColorFactor's alpha (sections 3.9.4, 3.9.5),
// as three.js's GLTFLoader reads them; the default material is opaque and single-sided.
void read_alpha_and_sides(const tinygltf::Material& g, Material& m) {
    const std::vector<double>& f = g.pbrMetallicRoughness.baseColorFactor;
    m.alpha = f.size() >= 4 && std::isfinite(f[3]) ? std::clamp(float(f[3]), 0.0f, 1.0f) : 1.0f;
    m.alpha_mode = g.alphaMode == "MASK"    ? AlphaMode::Mask
                   : g.alphaMode == "BLEND" ? AlphaMode::Blend
                                            : AlphaMode::Opaque;
    m.alpha_cutoff = std::isfinite(g.alphaCutoff) ? float(std::max(g.alphaCutoff, 0.0)) : 0.5f;
    m.sides = g.doubleSided ? FaceSides::Double : FaceSides::Front;
}

// three-vrm's MToonMaterialLoaderPlugin: an MToon material's mesh gets renderOrder
// renderQueueOffsetNumber + (transparentWithZWrite ? 0 : 19), and the z-write flag sets depthWrite.
void mtoon_render_order(Material& m, bool z_write, double queue_offset) {
    m.blend_depth_write = z_write;
    m.render_order = (z_write ? 0 : 19) + int(std::clamp(queue_offset, -1e6, 1e6));
}

bool keyword_on(const tinygltf::Value& props, const char* key) {
    if (!props.IsObject() || !props.Has("keywordMap")) return false;
    const tinygltf::Value& k = props.Get("keywordMap");
    return k.IsObject() && k.Has(key) && k.Get(key).IsBool() && k.Get(key).Get<bool>();
}

// Builds Mesh materials from glTF materials on first use, decoding each image once.
class MaterialTable {
public:
    MaterialTable(const tinygltf::Model& model, const AccessorReader& reader, const std::string& path, Mesh& mesh)
        : model_(model),
          reader_(reader),
          path_(path),
          mesh_(mesh),
          images_(model.images.size()),
          tried_(model.images.size(), 0),
          index_(model.materials.size() + 1, kNone) {
        const auto vrm = model.extensions.find("VRM");
        if (vrm != model.extensions.end() && vrm->second.IsObject() && vrm->second.Has("materialProperties")) {
            const tinygltf::Value& list = vrm->second.Get("materialProperties");
            if (list.IsArray()) v0_ = &list;
        }
        if (v0_) v0_queue_maps();
    }

    // Mesh material index for glTF material `gltf` (-1 or out of range: the default material,
    // base colour 1 as section 3.9.6 defines).
    uint32_t index(int gltf) {
        const size_t slot =
            gltf >= 0 && size_t(gltf) < model_.materials.size() ? size_t(gltf) : model_.materials.size();
        if (index_[slot] == kNone) {
            index_[slot] = uint32_t(mesh_.materials.size());
            Material fallback{"default", glm::vec3(1.0f)};
            fallback.sides = FaceSides::Front;  // section 3.9.6: single-sided, opaque
            mesh_.materials.push_back(slot == model_.materials.size() ? fallback : build(slot));
        }
        return index_[slot];
    }

    // TEXCOORD set the material's base colour texture uses (section 3.9.2 texCoord).
    int uv_set(int gltf) const {
        if (gltf < 0 || size_t(gltf) >= model_.materials.size()) return 0;
        return std::clamp(model_.materials[size_t(gltf)].pbrMetallicRoughness.baseColorTexture.texCoord, 0, 7);
    }

private:
    static constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

    // VRM 0.x blending as three-vrm's VRMMaterialsV0CompatPlugin turns it into glTF and MToon 1.0:
    // MToon's keywords _ALPHABLEND_ON / _ALPHATEST_ON (cutoff _Cutoff), _ZWrite, _CullMode 0 for
    // double-sided, _Color's alpha as written; the VRM/Unlit* shaders by name (their whole _Color
    // gamma-decoded, alpha too, and sides as the glTF material says).
    void v0_alpha_and_sides(const tinygltf::Value& props, const std::string& shader, Material& m) const {
        const tinygltf::Value& f = props.Has("floatProperties") ? props.Get("floatProperties") : props;
        const tinygltf::Value& v = props.Has("vectorProperties") ? props.Get("vectorProperties") : props;
        const float alpha = json_numbers(v, "_Color", {1, 1, 1, 1})[3];
        bool blend = false, z_write = false, cutout = false;
        if (shader == "VRM/MToon") {
            blend = keyword_on(props, "_ALPHABLEND_ON");
            z_write = blend && json_number(f, "_ZWrite", 0.0) == 1.0;
            cutout = keyword_on(props, "_ALPHATEST_ON");
            m.alpha = std::clamp(alpha, 0.0f, 1.0f);
            m.sides = json_number(f, "_CullMode", 2.0) == 0.0 ? FaceSides::Double : FaceSides::Front;
        } else {
            z_write = shader == "VRM/UnlitTransparentZWrite";
            blend = z_write || shader == "VRM/UnlitTransparent";
            cutout = shader == "VRM/UnlitCutout";
            m.alpha = std::clamp(std::pow(std::max(alpha, 0.0f), 2.2f), 0.0f, 1.0f);
        }
        m.alpha_mode = blend ? AlphaMode::Blend : cutout ? AlphaMode::Mask : AlphaMode::Opaque;
        m.alpha_cutoff = cutout ? float(std::max(json_number(f, "_Cutoff", 0.5), 0.0)) : 0.5f;
        mtoon_render_order(m, z_write, v0_queue_offset(props, shader));
    }

    // VRM 0.x renderQueue of a transparent material as a 1.0 renderQueueOffsetNumber: the
    // queues in use, in order, mapped to -n+1..0 (transparent, clamped at -9) or 0..n-1 (with
    // z-write, clamped at 9), as three-vrm's _populateRenderQueueMap does.
    static bool v0_transparent(const tinygltf::Value& props, const std::string& shader, bool* z_write) {
        const tinygltf::Value& f = props.Has("floatProperties") ? props.Get("floatProperties") : props;
        const bool unlit_z = shader == "VRM/UnlitTransparentZWrite";
        const bool has_blend = props.Has("keywordMap") && props.Get("keywordMap").IsObject() &&
                               props.Get("keywordMap").Has("_ALPHABLEND_ON");
        *z_write = json_number(f, "_ZWrite", 0.0) == 1.0 || unlit_z;
        return has_blend || shader == "VRM/UnlitTransparent" || unlit_z;
    }
    static std::string shader_of(const tinygltf::Value& props) {
        return props.IsObject() && props.Has("shader") && props.Get("shader").IsString()
                   ? props.Get("shader").Get<std::string>()
                   : std::string();
    }
    void v0_queue_maps() {
        std::set<double> plain, z;
        for (size_t i = 0; i < v0_->ArrayLen(); ++i) {
            const tinygltf::Value& props = v0_->Get(int(i));
            bool z_write = false;
            if (!props.IsObject() || !v0_transparent(props, shader_of(props), &z_write)) continue;
            if (props.Has("renderQueue") && props.Get("renderQueue").IsNumber())
                (z_write ? z : plain).insert(props.Get("renderQueue").GetNumberAsDouble());
        }
        int i = 0;
        for (double q : plain) queue_plain_[q] = std::clamp(i++ - int(plain.size()) + 1, -9, 0);
        i = 0;
        for (double q : z) queue_z_[q] = std::clamp(i++, 0, 9);
    }
    double v0_queue_offset(const tinygltf::Value& props, const std::string& shader) const {
        bool z_write = false;
        if (!v0_transparent(props, shader, &z_write) || !props.Has("renderQueue") ||
            !props.Get("renderQueue").IsNumber())
            return 0.0;
        const auto& map = z_write ? queue_z_ : queue_plain_;
        const auto it = map.find(props.Get("renderQueue").GetNumberAsDouble());
        return it == map.end() ? 0.0 : it->second;
    }

    Material build(size_t i) {
        const tinygltf::Material& g = model_.materials[i];
        Material m;
        m.name = g.name.empty() ? "material " + std::to_string(i) : g.name;
        const std::vector<double>& f = g.pbrMetallicRoughness.baseColorFactor;  // linear RGBA
        for (size_t k = 0; k < 3 && k < f.size(); ++k)
            m.diffuse[int(k)] = std::isfinite(f[k]) ? std::clamp(float(f[k]), 0.0f, 1.0f) : 1.0f;
        if (f.size() < 3) m.diffuse = glm::vec3(1.0f);
        int texture = g.pbrMetallicRoughness.baseColorTexture.index;
        std::optional<glm::mat3> base_transform;
        if (texture >= 0) {
            const auto& extensions = g.pbrMetallicRoughness.baseColorTexture.extensions;
            if (const auto it = extensions.find("KHR_texture_transform"); it != extensions.end())
                base_transform = khr_texture_transform(it->second);
        }

        read_alpha_and_sides(g, m);
        const auto v1 = g.extensions.find("VRMC_materials_mtoon");
        if (v1 != g.extensions.end()) {
            const tinygltf::Value& e = v1->second;
            add_mtoon(vrm1_mtoon(g, e), m);
            const bool z_write = e.IsObject() && e.Has("transparentWithZWrite") &&
                                 e.Get("transparentWithZWrite").IsBool() && e.Get("transparentWithZWrite").Get<bool>();
            mtoon_render_order(m, z_write, json_number(e, "renderQueueOffsetNumber", 0.0));
        } else if (v0_ != nullptr && i < v0_->ArrayLen()) {
            const tinygltf::Value& props = v0_->Get(int(i));
            const std::string shader = props.IsObject() && props.Has("shader") && props.Get("shader").IsString()
                                           ? props.Get("shader").Get<std::string>()
                                           : std::string();
            if (shader == "VRM/MToon" || shader.rfind("VRM/Unlit", 0) == 0) {
                // Like three-vrm: the v0 properties replace the glTF material's colour and texture.
                const tinygltf::Value& v = props.Has("vectorProperties") ? props.Get("vectorProperties") : props;
                std::vector<float> c = gamma_decode(json_numbers(v, "_Color", {1, 1, 1}));
                m.diffuse = glm::clamp(glm::vec3(c[0], c[1], c[2]), 0.0f, 1.0f);
                v0_alpha_and_sides(props, shader, m);
                const int main = json_texture_index(
                    props.Has("textureProperties") ? props.Get("textureProperties") : props, "_MainTex");
                if (main >= 0) texture = main;
                const std::optional<glm::mat3> main_transform = vrm0_main_texture_transform(v);
                if (main >= 0) base_transform = main_transform;
                // unlit: an MToon whose shade colour and shade multiply texture are the lit ones
                add_mtoon(shader == "VRM/MToon" ? vrm0_mtoon(props)
                                                : vrm0_unlit(m.diffuse, main, main_transform.value_or(glm::mat3(1.0f))),
                          m);
            }
        }
        if (texture >= 0) m.texture = texture_of(texture, m.name);
        if (m.texture && base_transform && *base_transform != glm::mat3(1.0f))
            m.uv_transforms["base-color-texture"] = *base_transform;
        // three-vrm removes KHR_materials_unlit from a material that has MToon.
        m.unlit = m.mtoon.empty() && g.extensions.count("KHR_materials_unlit") > 0;
        return m;
    }

    // A VRM material's MToon values, and its textures decoded.
    void add_mtoon(const VrmMaterial& vrm, Material& m) {
        m.mtoon = vrm.values;
        for (const auto& [key, index] : vrm.textures)
            if (auto t = texture_of(index, m.name)) {
                m.mtoon_textures[key] = std::move(t);
                const auto transform = vrm.uv_transforms.find(key);
                if (transform != vrm.uv_transforms.end() && transform->second != glm::mat3(1.0f))
                    m.uv_transforms[key] = transform->second;
            }
    }

    std::shared_ptr<const Texture> texture_of(int texture, const std::string& material) {
        if (size_t(texture) >= model_.textures.size()) {
            mesh_.warnings.push_back(path_ + ": material '" + one_line(material) + "' refers to texture " +
                                     std::to_string(texture) + ", which does not exist; using the base colour");
            return nullptr;
        }
        const int image = model_.textures[size_t(texture)].source;
        if (image < 0 || size_t(image) >= model_.images.size()) {  // e.g. KHR_texture_basisu / EXT_texture_webp only
            mesh_.warnings.push_back(path_ + ": texture " + std::to_string(texture) +
                                     " has no image Inkshade can decode (PNG or JPEG); using the base colour");
            return nullptr;
        }
        if (!tried_[size_t(image)]) {
            tried_[size_t(image)] = 1;
            images_[size_t(image)] = decode_image(size_t(image));
        }
        return images_[size_t(image)];
    }

    std::shared_ptr<const Texture> decode_image(size_t i) {
        const tinygltf::Image& image = model_.images[i];
        const std::string label = image.uri.empty() ? "image " + std::to_string(i) : image.uri;
        const std::string source = path_ + "#image " + std::to_string(i);
        std::string problem;
        std::shared_ptr<const Texture> texture;
        if (image.bufferView >= 0) {
            if (size_t(image.bufferView) >= model_.bufferViews.size()) {
                problem = "bufferView " + std::to_string(image.bufferView) + " does not exist";
            } else {
                try {
                    const unsigned char* bytes =
                        reader_.buffer_view_bytes(image.bufferView, "image " + std::to_string(i));
                    texture =
                        decode_texture(bytes, model_.bufferViews[size_t(image.bufferView)].byteLength, source, problem);
                } catch (const InputError& e) {  // a bad image range costs the texture, not the mesh
                    problem = std::string(e.what()).substr(path_.size() + 2);
                }
            }
        } else if (!image.image.empty()) {  // data: URI, kept by keep_encoded_image
            texture = decode_texture(image.image.data(), image.image.size(), source, problem);
        } else if (!image.uri.empty()) {
            std::filesystem::path dir = std::filesystem::path(path_).parent_path();
            return load_texture_or_warn(path_, percent_decode(image.uri),
                                        {dir.empty() ? std::filesystem::path(".") : dir}, mesh_.warnings);
        } else {
            problem = "no image data";
        }
        if (!texture) mesh_.warnings.push_back(texture_warning(path_, label, problem));
        return texture;
    }

    const tinygltf::Model& model_;
    const AccessorReader& reader_;
    const std::string& path_;
    Mesh& mesh_;
    std::vector<std::shared_ptr<const Texture>> images_;
    std::vector<char> tried_;
    std::vector<uint32_t> index_;  // glTF material (last slot: default) -> Mesh material
    const tinygltf::Value* v0_ = nullptr;
    std::map<double, int> queue_plain_, queue_z_;  // v0_queue_maps
};

// --- assembling the mesh ------------------------------------------------------------------

// Appends primitives to one Mesh. Attributes present in only some primitives are completed
// (uvs with 0, colours with the material colour) or dropped (normals: load_mesh computes them).
class MeshBuilder {
public:
    MeshBuilder(const tinygltf::Model& model, const std::string& path, Mesh& mesh, const AccessorReader& reader)
        : model_(model), path_(path), mesh_(mesh), reader_(reader), materials_(model, reader_, path, mesh) {}

    // A mesh instance, each primitive deformed by the pose (morph targets, skin) first.
    void add(const Instance& instance, const GltfPose& pose) {
        const tinygltf::Mesh& gm = model_.meshes[size_t(instance.mesh)];
        for (size_t p = 0; p < gm.primitives.size(); ++p)
            add_primitive(gm.primitives[p], instance, pose,
                          "mesh " + std::to_string(instance.mesh) + " primitive " + std::to_string(p));
    }

    void finish() {
        if (!normals_complete_) mesh_.normals.clear();
        if (skipped_ > 0)
            mesh_.warnings.push_back(path_ + ": " + std::to_string(skipped_) + " point or line primitive" +
                                     (skipped_ > 1 ? "s" : "") + " skipped (only triangles are drawn)");
    }
    size_t skipped() const { return skipped_; }

private:
    void add_primitive(const tinygltf::Primitive& prim, const Instance& instance, const GltfPose& pose,
                       const std::string& where) {
        const glm::dmat4& transform = instance.transform;
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            ++skipped_;
            return;
        }
        const auto attribute = [&](const std::string& name) {
            auto it = prim.attributes.find(name);
            return it == prim.attributes.end() ? -1 : it->second;
        };
        const int position = attribute("POSITION");
        if (position < 0) {  // section 3.7.2.1: such a primitive is not rendered
            mesh_.warnings.push_back(path_ + ": " + where + " has no POSITION attribute; skipped");
            return;
        }
        int comps = 0;
        std::vector<float> pos = reader_.floats(position, "POSITION of " + where, {3}, comps);
        const size_t n = pos.size() / 3;
        if (n == 0) return;
        std::vector<uint32_t> corners;
        if (prim.indices >= 0) {
            corners = reader_.indices(prim.indices, "indices of " + where, n);
        } else {
            corners.resize(n);
            for (size_t i = 0; i < n; ++i) corners[i] = uint32_t(i);
        }
        const size_t base = mesh_.positions.size();
        if (n > kMaxVertices - base)
            reader_.fail("more than " + std::to_string(kMaxVertices) + " vertices in the scene");

        // Triangles (section 3.7.2.1 gives the strip and fan orders); a mirroring transform
        // swaps two corners so the front face stays counter-clockwise.
        const bool mirror = glm::determinant(glm::dmat3(transform)) < 0.0;
        std::vector<glm::uvec3> tris;
        auto emit = [&](uint32_t a, uint32_t b, uint32_t c) {
            tris.push_back(mirror ? glm::uvec3(a, c, b) : glm::uvec3(a, b, c));
        };
        const size_t m = corners.size();
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            if (m % 3 != 0)
                mesh_.warnings.push_back(path_ + ": " + where + " has " + std::to_string(m) +
                                         " indices, not a multiple of 3; the rest is ignored");
            for (size_t i = 0; i + 2 < m; i += 3) emit(corners[i], corners[i + 1], corners[i + 2]);
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            for (size_t i = 0; i + 2 < m; ++i) emit(corners[i], corners[i + 1 + i % 2], corners[i + 2 - i % 2]);
        } else {
            for (size_t i = 1; i + 1 < m; ++i) emit(corners[i], corners[i + 1], corners[0]);
        }
        if (tris.size() > kMaxTriangles - mesh_.triangles.size())
            reader_.fail("more than " + std::to_string(kMaxTriangles) + " triangles in the scene");

        // Attributes, read (and checked) before anything is appended.
        std::vector<float> nrm, uv, col;
        int col_comps = 0;
        const int normal = attribute("NORMAL");
        if (normal >= 0) nrm = reader_.floats(normal, "NORMAL of " + where, {3}, comps);
        const int uv_set = materials_.uv_set(prim.material);
        const int texcoord = attribute("TEXCOORD_" + std::to_string(uv_set));
        if (texcoord >= 0)
            uv = reader_.floats(texcoord, "TEXCOORD_" + std::to_string(uv_set) + " of " + where, {2}, comps);
        const int color = attribute("COLOR_0");
        if (color >= 0) col = reader_.floats(color, "COLOR_0 of " + where, {3, 4}, col_comps);
        auto same_count = [&](const std::vector<float>& a, size_t c, const char* name) {
            if (!a.empty() && a.size() / c != n)
                reader_.fail(std::string(name) + " of " + where + " has " + std::to_string(a.size() / c) +
                             " elements but POSITION has " + std::to_string(n));
        };
        same_count(nrm, 3, "NORMAL");
        same_count(uv, 2, "TEXCOORD");
        if (col_comps > 0) same_count(col, size_t(col_comps), "COLOR_0");
        pose.deform(size_t(instance.node), prim, pos, nrm, where);

        const uint32_t material = materials_.index(prim.material);
        const glm::vec3 base_colour = mesh_.materials[material].diffuse;
        const glm::mat3 normal_matrix = glm::mat3(glm::inverseTranspose(glm::dmat3(transform)));

        for (size_t i = 0; i < n; ++i) {
            glm::dvec4 p = transform * glm::dvec4(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], 1.0);
            mesh_.positions.emplace_back(float(p.x), float(p.y), float(p.z));
        }
        if (normals_complete_ && nrm.empty()) {
            normals_complete_ = false;
            mesh_.normals.clear();
        } else if (normals_complete_) {
            for (size_t i = 0; i < n; ++i) {
                glm::vec3 v = normal_matrix * glm::vec3(nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]);
                float len = glm::length(v);
                mesh_.normals.push_back(len > 0.0f ? v / len : v);  // zero stays zero: load_mesh repairs it
            }
        }
        // glTF texture coordinates start at the image's top-left (section 3.7.2.1); Mesh::uvs
        // use OBJ's bottom-left origin.
        if (!uv.empty() && mesh_.uvs.size() < base) mesh_.uvs.resize(base, glm::vec2(0.0f));
        if (!uv.empty()) {
            for (size_t i = 0; i < n; ++i) mesh_.uvs.emplace_back(uv[2 * i], 1.0f - uv[2 * i + 1]);
        } else if (!mesh_.uvs.empty()) {
            mesh_.uvs.resize(base + n, glm::vec2(0.0f));
        }
        // COLOR_0 multiplies the base colour factor (section 3.9.2); Mesh::colors replace the
        // material colour, so they carry the product, and other primitives their own colour.
        if (!col.empty() && mesh_.colors.empty() && base > 0) {
            mesh_.colors.reserve(base + n);
            for (const Range& r : ranges_) mesh_.colors.resize(r.end, r.colour);
        }
        if (!col.empty()) {
            const size_t c = size_t(col_comps);
            for (size_t i = 0; i < n; ++i)
                mesh_.colors.push_back(glm::clamp(glm::vec3(col[c * i], col[c * i + 1], col[c * i + 2]), 0.0f, 1.0f) *
                                       base_colour);
        } else if (!mesh_.colors.empty()) {
            mesh_.colors.resize(base + n, base_colour);
        }
        ranges_.push_back({base + n, base_colour});

        for (const glm::uvec3& t : tris) {
            mesh_.triangles.push_back(glm::uvec3(base) + t);
            mesh_.face_materials.push_back(material);
        }
    }

    struct Range {
        size_t end;  // one past the primitive's last vertex
        glm::vec3 colour;
    };

    const tinygltf::Model& model_;
    const std::string& path_;
    Mesh& mesh_;
    const AccessorReader& reader_;
    MaterialTable materials_;
    std::vector<Range> ranges_;
    bool normals_complete_ = true;
    size_t skipped_ = 0;
};

// Extensions that change what the geometry bytes mean: without them nothing can be read.
void check_required_extensions(const tinygltf::Model& model, const std::string& path) {
    for (const std::string& e : model.extensionsRequired)
        if (e == "KHR_draco_mesh_compression" || e == "EXT_meshopt_compression" || e == "KHR_meshopt_compression")
            throw InputError(path, "requires extension " + e + " (compressed geometry), which is not supported");
}

}  // namespace

Mesh read_gltf(const std::string& path, const Pose& pose) {
    FileBytes file(path);
    const std::string_view bytes = file.view();
    const std::string ext = lower_ascii(std::filesystem::path(path).extension().string());
    // By content where it is unambiguous: GLB magic, or JSON's opening brace (a .gltf renamed
    // .glb); otherwise the extension decides, and its reader's errors say what is wrong.
    const size_t first = bytes.find_first_not_of(" \t\r\n");
    const bool json_text = first != std::string_view::npos && bytes[first] == '{';
    const bool binary = bytes.substr(0, 4) == "glTF" || (ext != ".gltf" && !json_text);

    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&file_exists, &expand_path, &read_whole_file, &write_whole_file, nullptr});
    loader.SetImageLoader(&keep_encoded_image, nullptr);
    std::filesystem::path dir = std::filesystem::path(path).parent_path();
    const std::string base_dir = dir.empty() ? std::string(".") : dir.string();

    tinygltf::Model model;
    std::string err, warn;
    bool ok = false;
    try {
        if (binary) {
            const size_t length = check_glb(bytes, path);
            check_json_depth(bytes.substr(20, le32(bytes.data() + 12)), path);
            ok = loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                             unsigned(length), base_dir);
        } else {
            if (bytes.size() > std::numeric_limits<unsigned>::max()) throw InputError(path, "JSON larger than 4 GiB");
            check_json_depth(bytes, path);
            ok = loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), base_dir);
        }
    } catch (const InputError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw InputError(path, "out of memory while parsing the glTF JSON");
    } catch (const std::out_of_range&) {  // tinygltf indexes some empty vectors with .at()
        throw InputError(path, "malformed glTF (an empty buffer or image where data is required)");
    } catch (const std::exception& e) {
        throw InputError(path, "malformed glTF (" + one_line(e.what()) + ")");
    }
    if (!ok) throw InputError(path, explain_parse_error(err));
    if (!model.asset.version.empty() && model.asset.version[0] != '2')
        throw InputError(path, "glTF version " + one_line(model.asset.version) + " is not supported (glTF 2.0 only)");
    check_required_extensions(model, path);

    Mesh mesh;
    const AccessorReader reader(model, path);
    const GltfPose posed(model, path, pose, reader, &local_transform, mesh.warnings);
    MeshBuilder builder(model, path, mesh, reader);
    const SceneNodes nodes = scene_nodes(model, path, posed);
    for (const Instance& instance : nodes.meshes) builder.add(instance, posed);
    builder.finish();
    add_gltf_cameras(model, nodes.cameras_and_lights, path, mesh);
    add_gltf_lights(model, nodes.cameras_and_lights, path, mesh);
    mesh.pose_names = read_gltf_pose_names(model, path, reader);
    if (mesh.triangles.empty()) {
        if (builder.skipped() > 0)
            throw InputError(path, "no triangles (only point or line primitives: " + std::to_string(builder.skipped()) +
                                       " skipped)");
        throw InputError(path, "no triangles (the scene has no mesh)");
    }
    return mesh;
}

}  // namespace inkshade::io
