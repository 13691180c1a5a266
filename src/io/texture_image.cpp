// Texture decoding through stb_image (Debian libstb, as image_file.cpp uses it). The header is
// read first (stbi_info_from_memory) so an image claiming 100000 x 100000 pixels, or more
// pixels than its bytes can encode, is refused before anything is allocated.
#include "io/texture_image.hpp"

#include <stb_image.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>
#include <system_error>

#include "inkshade/error.hpp"
#include "io/file_bytes.hpp"

namespace inkshade::io {
namespace {

// A file name as it may appear in a one-line message: control bytes become '?', long names are cut.
std::string printable(const std::string& name) {
    std::string s;
    for (char c : name.substr(0, 160)) s += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
    if (name.size() > 160) s += "...";
    return s;
}

// stb_image's PNG reader grows its IDAT buffer to the length a chunk header claims before it
// checks that the bytes are there (2 GiB for a 40-byte file). Every chunk must lie inside the
// data, so nothing it allocates for chunks exceeds twice the encoded size.
bool png_chunks_fit(const unsigned char* bytes, size_t size, std::string& problem) {
    static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (size < 8 || std::memcmp(bytes, kSignature, 8) != 0) return true;  // not PNG
    for (size_t pos = 8; pos + 8 <= size;) {
        const uint32_t length = uint32_t(bytes[pos]) << 24 | uint32_t(bytes[pos + 1]) << 16 |
                                uint32_t(bytes[pos + 2]) << 8 | bytes[pos + 3];
        if (length > size - pos - 8 || size - pos - 8 - length < 4) {  // data and CRC
            problem = "corrupt image data (PNG chunk of " + std::to_string(length) + " bytes at offset " +
                      std::to_string(pos) + " runs past the end of the " + std::to_string(size) + "-byte image)";
            return false;
        }
        if (std::memcmp(bytes + pos + 4, "IEND", 4) == 0) break;
        pos += 12 + size_t(length);
    }
    return true;
}

}  // namespace

std::string texture_warning(const std::string& mesh_file, const std::string& name, const std::string& problem) {
    return mesh_file + ": texture '" + printable(name) + "' not loaded (" + problem + "); using the base colour";
}

std::shared_ptr<const Texture> decode_texture(const unsigned char* bytes, size_t size, const std::string& source,
                                              std::string& problem) {
    if (bytes == nullptr || size == 0) {
        problem = "no image data";
        return nullptr;
    }
    if (size > size_t(INT_MAX)) {  // stb_image takes an int length
        problem = "encoded image larger than 2 GiB";
        return nullptr;
    }
    int w = 0, h = 0, comp = 0;
    if (!stbi_info_from_memory(bytes, int(size), &w, &h, &comp)) {
        const char* why = stbi_failure_reason();
        problem = std::string("not a decodable image (") + (why ? why : "unknown format") + ")";
        return nullptr;
    }
    if (w <= 0 || h <= 0 || w > kMaxTextureSide || h > kMaxTextureSide) {
        problem = std::to_string(w) + " x " + std::to_string(h) + " pixels is over the limit of " +
                  std::to_string(kMaxTextureSide) + " per side";
        return nullptr;
    }
    // The decoder allocates what the header claims before it finds the data missing: a claim
    // the encoded bytes cannot back is refused before anything is allocated.
    if (uint64_t(w) * uint64_t(h) > uint64_t(size) * kMaxPixelsPerEncodedByte) {
        problem = std::to_string(w) + " x " + std::to_string(h) + " pixels cannot be encoded in " +
                  std::to_string(size) + " bytes (corrupt header?)";
        return nullptr;
    }
    if (!png_chunks_fit(bytes, size, problem)) return nullptr;
    int dw = 0, dh = 0;
    unsigned char* pixels = stbi_load_from_memory(bytes, int(size), &dw, &dh, &comp, 4);
    if (pixels == nullptr) {
        const char* why = stbi_failure_reason();
        problem = std::string("corrupt image data (") + (why ? why : "decoder failed") + ")";
        return nullptr;
    }
    struct Free {
        unsigned char* p;
        ~Free() { stbi_image_free(p); }
    } release{pixels};
    if (dw != w || dh != h) {  // the header and the data disagree: trust neither
        problem = "image size changed while decoding";
        return nullptr;
    }
    auto texture = std::make_shared<Texture>();
    texture->source = source;
    texture->width = w;
    texture->height = h;
    texture->rgba.assign(pixels, pixels + size_t(w) * size_t(h) * 4);
    return texture;
}

std::shared_ptr<const Texture> load_texture_file(const std::filesystem::path& file, std::string& problem) {
    const std::string path = file.string();
    std::error_code ec;
    const auto size = std::filesystem::file_size(file, ec);
    if (!ec && size > kMaxTextureFileBytes) {
        problem = "file larger than " + std::to_string(kMaxTextureFileBytes >> 20) + " MiB";
        return nullptr;
    }
    try {
        FileBytes bytes(path);  // regular files only: a device or FIFO cannot stall the load
        return decode_texture(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), path, problem);
    } catch (const InputError& e) {
        std::string what = e.what();  // "PATH: problem"
        problem = what.rfind(path + ": ", 0) == 0 ? what.substr(path.size() + 2) : what;
        return nullptr;
    }
}

std::shared_ptr<const Texture> load_texture_or_warn(const std::string& mesh_file, const std::string& name,
                                                    const std::vector<std::filesystem::path>& dirs,
                                                    std::vector<std::string>& warnings) {
    if (name.empty() || name.find('\0') != std::string::npos) {
        warnings.push_back(texture_warning(mesh_file, name, "bad file name"));
        return nullptr;
    }
    std::string slashed = name;  // exporters on Windows write "textures\skin.png"
    std::replace(slashed.begin(), slashed.end(), '\\', '/');
    std::vector<std::filesystem::path> candidates;
    const std::filesystem::path given(slashed);
    if (given.is_absolute() || dirs.empty()) {
        candidates.push_back(given);
    } else {
        for (const auto& dir : dirs) candidates.push_back(dir / given);
    }
    // The first candidate that exists is the one meant; report its problem, else "not found".
    for (const auto& candidate : candidates) {
        std::error_code ec;
        if (!std::filesystem::exists(candidate, ec)) continue;
        std::string problem;
        if (auto texture = load_texture_file(candidate, problem)) return texture;
        warnings.push_back(texture_warning(mesh_file, name, problem));
        return nullptr;
    }
    warnings.push_back(texture_warning(mesh_file, name, "file not found"));
    return nullptr;
}

}  // namespace inkshade::io
