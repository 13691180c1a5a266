// load_mesh: dispatch on the extension, validate what the reader returned, weld soups and
// make sure there are normals. The readers parse; everything format-independent is here.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/builtin_models.hpp"
#include "geometry/normals.hpp"
#include "geometry/weld.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "io/readers.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {
namespace {

std::string lowercase(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What every reader's result must satisfy before anything downstream trusts it. Binary
// formats have no line numbers, so the vertex or triangle index names the culprit.
void validate(Mesh& mesh, const std::string& path) {
    const size_t n = mesh.positions.size();
    // A reader that produced mismatched attribute arrays is a bug; drop rather than misindex.
    if (mesh.normals.size() != n) mesh.normals.clear();
    if (mesh.colors.size() != n) mesh.colors.clear();
    if (mesh.uvs.size() != n) mesh.uvs.clear();
    if (mesh.face_materials.size() != mesh.triangles.size()) mesh.face_materials.clear();

    for (size_t i = 0; i < n; ++i)
        if (!finite(mesh.positions[i]))
            throw InputError(path, "vertex " + std::to_string(i) + " has a non-finite coordinate");
    for (size_t i = 0; i < mesh.colors.size(); ++i)
        if (!finite(mesh.colors[i])) throw InputError(path, "vertex " + std::to_string(i) + " has a non-finite colour");
    for (size_t i = 0; i < mesh.uvs.size(); ++i)
        if (!std::isfinite(mesh.uvs[i].x) || !std::isfinite(mesh.uvs[i].y))
            throw InputError(path, "vertex " + std::to_string(i) + " has a non-finite texture coordinate");
    if (mesh.triangles.empty()) throw InputError(path, "no triangles");
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (mesh.triangles[t][k] >= n)
                throw InputError(path, "triangle " + std::to_string(t) + " refers to vertex " +
                                           std::to_string(mesh.triangles[t][k]) + " but the mesh has " +
                                           std::to_string(n) + " vertices");
    for (uint32_t m : mesh.face_materials)
        if (m >= mesh.materials.size()) {
            mesh.face_materials.clear();
            break;
        }
}

// A mesh in which no vertex is used twice is a soup whatever its format (PLY and OFF
// exporters write those too): weld it so adjacency and smooth normals exist.
bool shares_no_vertex(const Mesh& mesh) {
    if (mesh.triangles.size() < 2) return false;
    std::vector<uint8_t> used(mesh.positions.size(), 0);
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            if (used[t[k]]++) return false;
    return true;
}

}  // namespace

Mesh load_mesh(const std::string& path, const LoadOptions& options) {
    constexpr std::string_view kBuiltin = "builtin:";
    if (path.starts_with(kBuiltin)) {
        Mesh mesh = builtin::by_name(path.substr(kBuiltin.size()));
        if (options.compute_normals) geometry::ensure_vertex_normals(mesh);
        return mesh;
    }

    std::string ext = lowercase(std::filesystem::path(path).extension().string());
    Mesh mesh;
    bool soup = io::format_is_soup(ext);
    if (ext == ".obj") {
        bool obj_soup = false;
        mesh = io::read_obj(path, obj_soup);
        soup |= obj_soup;
    } else if (ext == ".stl") {
        mesh = io::read_stl(path);
    } else if (ext == ".ply") {
        mesh = io::read_ply(path);
    } else if (ext == ".off") {
        mesh = io::read_off(path);
    } else {
        throw InputError(path, (ext.empty() ? std::string("no file extension") : "unknown file extension " + io::quote_token(ext)) +
                                   " (supported: .obj .stl .ply .off)");
    }

    validate(mesh, path);
    // Not for OBJ with per-corner normals or uvs: those vertices are split on purpose.
    bool split_on_purpose = ext == ".obj" && (!mesh.normals.empty() || !mesh.uvs.empty());
    if (soup || (!split_on_purpose && shares_no_vertex(mesh))) {
        // Per-corner normals of a soup are facet normals; after merging, the first one of each
        // cluster would win, so recompute smooth ones instead.
        mesh.normals.clear();
        geometry::weld(mesh, geometry::WeldOptions{options.weld_epsilon});
    }
    if (options.compute_normals)
        geometry::ensure_vertex_normals(mesh);
    else if (!mesh.normals.empty() && !geometry::normals_are_sane(mesh))
        mesh.normals.clear();  // empty means "compute": better than passing NaNs on
    return mesh;
}

std::vector<std::string> builtin_model_names() { return builtin::names(); }

namespace io {

bool format_is_soup(const std::string& extension) {
    std::string ext = lowercase(extension);
    if (ext.starts_with('.')) ext.erase(0, 1);
    return ext == "stl";
}

}  // namespace io
}  // namespace inkshade
