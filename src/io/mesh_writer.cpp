// write_mesh (inkshade/mesh_writer.hpp): the mesh's triangles in world coordinates, the frame the camera
// files and the metadata's matrices place (docs/aov.md), for re-projection and point clouds.
#include <bit>
#include <cstdio>
#include <string>

#include "inkshade/error.hpp"
#include "inkshade/mesh_writer.hpp"
#include "io/atomic_file.hpp"

namespace inkshade {

namespace {

// Wavefront OBJ: "v x y z" (shortest round-trip text of each float), "f a b c" (1-based).
std::string format_obj(const Mesh& mesh) {
    std::string out = "# inkshade --export-mesh: world coordinates of the camera files\n";
    out.reserve(out.size() + mesh.positions.size() * 40 + mesh.triangles.size() * 24);
    char buf[96];
    for (const glm::vec3& p : mesh.positions) {
        std::snprintf(buf, sizeof buf, "v %.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z));
        out += buf;
    }
    for (const glm::uvec3& t : mesh.triangles) {
        std::snprintf(buf, sizeof buf, "f %u %u %u\n", t.x + 1, t.y + 1, t.z + 1);
        out += buf;
    }
    return out;
}

void put_le32(std::string& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xffu);
}

// PLY 1.0, binary little-endian (Turk 1994; the layout every point-cloud reader takes): float
// x, y, z per vertex, a uchar-counted int list per face.
std::string format_ply(const Mesh& mesh) {
    std::string out =
        "ply\nformat binary_little_endian 1.0\ncomment inkshade --export-mesh: world coordinates of "
        "the camera files\nelement vertex " +
        std::to_string(mesh.positions.size()) +
        "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
        std::to_string(mesh.triangles.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
    out.reserve(out.size() + mesh.positions.size() * 12 + mesh.triangles.size() * 13);
    for (const glm::vec3& p : mesh.positions)
        for (int k = 0; k < 3; ++k) put_le32(out, std::bit_cast<uint32_t>(p[k]));
    for (const glm::uvec3& t : mesh.triangles) {
        out += char(3);
        for (int k = 0; k < 3; ++k) put_le32(out, t[k]);
    }
    return out;
}

bool ends_with_nocase(const std::string& text, std::string_view suffix) {
    if (text.size() < suffix.size()) return false;
    for (size_t i = 0; i < suffix.size(); ++i) {
        const char c = text[text.size() - suffix.size() + i];
        if ((c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c) != suffix[i]) return false;
    }
    return true;
}

}  // namespace

bool is_mesh_export_path(const std::string& path) {
    return path.size() > 4 && (ends_with_nocase(path, ".obj") || ends_with_nocase(path, ".ply"));
}

void write_mesh(const std::string& path, const Mesh& mesh) {
    if (!is_mesh_export_path(path)) throw InputError(path + ": expected a .obj or .ply file name");
    io::write_file_atomic(path, ends_with_nocase(path, ".obj") ? format_obj(mesh) : format_ply(mesh));
}

}  // namespace inkshade
