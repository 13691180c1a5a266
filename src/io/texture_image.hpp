// Decoding base-colour textures (PNG, JPEG, BMP, TGA, GIF... whatever stb_image reads) for the
// mesh readers. A texture that cannot be had is never fatal: the caller gets null and a reason,
// and the mesh keeps its base colour (Mesh::warnings tells the user).
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::io {

// Largest accepted side: 16384 is the GL_MAX_TEXTURE_SIZE of current desktop GPUs, and caps a
// decoded texture at 1 GiB whatever a header claims.
constexpr int kMaxTextureSide = 16384;
// Most pixels one encoded byte can stand for: deflate packs at most 1032 bytes into one, and a
// 1-bit PNG holds 8 pixels per byte (JPEG, GIF, BMP/TGA/PSD run lengths pack fewer). An image
// claiming more pixels than its size allows is corrupt and refused before decoding: a 1 KiB
// file may claim at most 8.4 million pixels, not 16384 x 16384.
constexpr uint64_t kMaxPixelsPerEncodedByte = 8 * 1032;
// Largest encoded image file read (a 16384^2 PNG is far smaller in practice).
constexpr size_t kMaxTextureFileBytes = size_t(1) << 30;

// Decodes an encoded image to RGBA8, top row first. Returns null and sets `problem` (one line,
// no file name) on unsupported or corrupt data or a size over the limits.
std::shared_ptr<const Texture> decode_texture(const unsigned char* bytes, size_t size, const std::string& source,
                                              std::string& problem);

// Reads and decodes an image file (regular files only). Null and `problem` as above, also for
// a missing or unreadable file.
std::shared_ptr<const Texture> load_texture_file(const std::filesystem::path& file, std::string& problem);

// load_texture_file for `name` as written in `mesh_file` (relative names are looked up in each
// of `dirs` in turn; Windows '\' separators are accepted). On failure appends
// "MESH_FILE: texture 'NAME' not loaded (PROBLEM); using the base colour" to `warnings`.
std::shared_ptr<const Texture> load_texture_or_warn(const std::string& mesh_file, const std::string& name,
                                                    const std::vector<std::filesystem::path>& dirs,
                                                    std::vector<std::string>& warnings);

// The one-line warning for a texture that could not be used.
std::string texture_warning(const std::string& mesh_file, const std::string& name, const std::string& problem);

}  // namespace inkshade::io
