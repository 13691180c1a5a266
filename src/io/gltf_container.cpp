// The glTF container (gltf_container.hpp): tinygltf (Debian's header-only tiny_gltf.h, compiled
// here) parses the JSON and loads buffers, but gets no file system of its own: buffers come
// through callbacks that only read regular files, and images are kept encoded for the material
// reader (gltf_materials.cpp), so a bad texture is a warning, never a failure. The GLB header
// and chunk table (glTF 2.0 section 4.4) and the JSON's nesting depth are checked here first.
#include "io/gltf_container.hpp"

#include <fstream>  // tiny_gltf.h's writers use std::ofstream but include <fstream> only without TINYGLTF_NO_FS

#define TINYGLTF_IMPLEMENTATION  // compiled here, configured as everywhere (io/tiny_gltf_config.hpp)
#include "io/tiny_gltf_config.hpp"

#include <bit>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/name_suggestion.hpp"
#include "inkshade/error.hpp"
#include "io/file_bytes.hpp"

namespace inkshade::io {
namespace {

constexpr size_t kMaxBufferFileBytes = size_t(4) << 30;  // GLB lengths are 32-bit anyway
// tinygltf copies `extensions` and `extras` into its Value type recursively (and destroys them
// recursively): JSON nested 100000 deep overflowed the stack. glTF itself nests about 8 deep.
constexpr size_t kMaxJsonDepth = 512;

// tinygltf's wording made to read like the other readers' messages.
std::string explain_parse_error(const std::string& err) {
    std::string line = printable_first_line(err);
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
        if (err) *err = printable_first_line(e.what());
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

// Extensions that change what the geometry bytes mean: without them nothing can be read.
void check_required_extensions(const tinygltf::Model& model, const std::string& path) {
    for (const std::string& e : model.extensionsRequired)
        if (e == "KHR_draco_mesh_compression" || e == "EXT_meshopt_compression" || e == "KHR_meshopt_compression")
            throw InputError(path, "requires extension " + e + " (compressed geometry), which is not supported");
}

// tinygltf's loader with Inkshade's file callbacks and image keeper.
void configure_loader(tinygltf::TinyGLTF& loader) {
    loader.SetFsCallbacks({&file_exists, &expand_path, &read_whole_file, &write_whole_file, nullptr});
    loader.SetImageLoader(&keep_encoded_image, nullptr);
}

// GLB (after check_glb) or JSON text into `model`; tinygltf's exceptions become InputErrors.
void parse_model(tinygltf::TinyGLTF& loader, std::string_view bytes, bool binary, const std::string& path,
                 tinygltf::Model& model) {
    std::filesystem::path dir = std::filesystem::path(path).parent_path();
    const std::string base_dir = dir.empty() ? std::string(".") : dir.string();
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
        throw InputError(path, "malformed glTF (" + printable_first_line(e.what()) + ")");
    }
    if (!ok) throw InputError(path, explain_parse_error(err));
}

}  // namespace

std::string printable_first_line(const std::string& s) {
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

void load_gltf_model(const std::string& path, tinygltf::Model& model) {
    FileBytes file(path);
    const std::string_view bytes = file.view();
    const std::string ext = lower_ascii(std::filesystem::path(path).extension().string());
    // By content where it is unambiguous: GLB magic, or JSON's opening brace (a .gltf renamed
    // .glb); otherwise the extension decides, and its reader's errors say what is wrong.
    const size_t first = bytes.find_first_not_of(" \t\r\n");
    const bool json_text = first != std::string_view::npos && bytes[first] == '{';
    const bool binary = bytes.substr(0, 4) == "glTF" || (ext != ".gltf" && !json_text);

    tinygltf::TinyGLTF loader;
    configure_loader(loader);
    parse_model(loader, bytes, binary, path, model);
    if (!model.asset.version.empty() && model.asset.version[0] != '2')
        throw InputError(
            path, "glTF version " + printable_first_line(model.asset.version) + " is not supported (glTF 2.0 only)");
    check_required_extensions(model, path);
}

}  // namespace inkshade::io
