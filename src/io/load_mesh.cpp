// load_mesh: dispatch on the extension, validate what the reader returned, weld soups and
// make sure there are normals. The readers parse; everything format-independent is here.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/name_suggestion.hpp"
#include "geometry/builtin_models.hpp"
#include "geometry/duplicate_faces.hpp"
#include "geometry/auto_smooth.hpp"
#include "geometry/normals.hpp"
#include "geometry/weld.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "io/readers.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {
namespace {

// Largest accepted coordinate magnitude. Cameras, bounding boxes and line projection work in
// float: a squared distance across a model spanning +-1e34 overflows, and auto-framing would
// put the eye at infinity. 1e15 leaves those products 7 orders of magnitude of headroom and is
// far beyond any real model (the Earth's orbit is 1.5e14 mm).
constexpr float kMaxCoordinate = 1e15f;
bool in_range(glm::vec3 v) {
    return std::abs(v.x) <= kMaxCoordinate && std::abs(v.y) <= kMaxCoordinate && std::abs(v.z) <= kMaxCoordinate;
}

// What every reader's result must satisfy before anything downstream trusts it. Binary
// formats have no line numbers, so the vertex or triangle index names the culprit.
void validate(Mesh& mesh, const std::string& path) {
    const size_t n = mesh.positions.size();
    // A reader that produced mismatched attribute arrays is a bug; drop rather than misindex.
    if (mesh.normals.size() != n) mesh.normals.clear();
    if (mesh.colors.size() != n) mesh.colors.clear();
    if (mesh.uvs.size() != n) mesh.uvs.clear();
    if (mesh.face_materials.size() != mesh.triangles.size()) mesh.face_materials.clear();
    if (mesh.face_objects.size() != mesh.triangles.size()) mesh.face_objects.clear();
    if (mesh.face_marks.size() != mesh.triangles.size()) mesh.face_marks.clear();
    for (uint32_t o : mesh.face_objects)
        if (o >= mesh.object_names.size()) {
            mesh.face_objects.clear();
            break;
        }

    for (size_t i = 0; i < n; ++i) {
        if (!is_finite(mesh.positions[i]))
            throw InputError(path, "vertex " + std::to_string(i) + " has a non-finite coordinate");
        if (!in_range(mesh.positions[i]))
            throw InputError(path,
                             "vertex " + std::to_string(i) + " has a coordinate beyond +-1e15 (too large to draw)");
    }
    for (size_t i = 0; i < mesh.colors.size(); ++i)
        if (!is_finite(mesh.colors[i]))
            throw InputError(path, "vertex " + std::to_string(i) + " has a non-finite colour");
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
    for (size_t l = 0; l < mesh.line_segments.size(); ++l)
        if (mesh.line_segments[l].x >= n || mesh.line_segments[l].y >= n)
            throw InputError(path, "line segment " + std::to_string(l) + " refers to a vertex the mesh does not have");
    for (uint32_t m : mesh.face_materials)
        if (m >= mesh.materials.size()) {
            mesh.face_materials.clear();
            break;
        }
}

// geometry::weld keeps the attributes of each cluster's first vertex, which would glue texture
// seams and colour boundaries (a textured soup would show the wrong texels). With uvs or
// colours, positions are welded alone to find the clusters, and each cluster is then split by
// its exact (uv, colour) values: vertices merge only where nothing but the index differs.
void weld_keeping_attributes(Mesh& mesh, float epsilon) {
    if (mesh.uvs.empty() && mesh.colors.empty()) {
        geometry::weld(mesh, geometry::WeldOptions{epsilon});
        return;
    }
    const size_t n = mesh.positions.size();
    Mesh probe;  // one degenerate "triangle" per vertex: after welding, probe.triangles[i].x is i's cluster
    probe.positions = mesh.positions;
    probe.triangles.resize(n);
    for (size_t i = 0; i < n; ++i) probe.triangles[i] = glm::uvec3(uint32_t(i));
    geometry::weld(probe, geometry::WeldOptions{epsilon});
    if (!probe.welded) return;

    constexpr uint32_t kNone = UINT32_MAX;
    const bool uvs = !mesh.uvs.empty(), colors = !mesh.colors.empty(), normals = mesh.normals.size() == n;
    std::vector<uint32_t> first(probe.positions.size(), kNone), next, source, remap(n);
    for (size_t v = 0; v < n; ++v) {
        const uint32_t cluster = probe.triangles[v].x;
        uint32_t prev = kNone, found = kNone;
        for (uint32_t r = first[cluster]; r != kNone; prev = r, r = next[r]) {
            const uint32_t s = source[r];
            if ((!uvs || mesh.uvs[s] == mesh.uvs[v]) && (!colors || mesh.colors[s] == mesh.colors[v])) {
                found = r;
                break;
            }
        }
        if (found == kNone) {
            found = uint32_t(source.size());
            source.push_back(uint32_t(v));
            next.push_back(kNone);
            (prev == kNone ? first[cluster] : next[prev]) = found;
        }
        remap[v] = found;
    }
    if (source.size() == n) return;  // every merge would have crossed a seam

    std::vector<glm::vec3> positions(source.size()), vnormals, vcolors;
    std::vector<glm::vec2> vuvs;
    for (size_t r = 0; r < source.size(); ++r) positions[r] = probe.positions[probe.triangles[source[r]].x];
    auto gather = [&](auto& out, const auto& in) {
        out.resize(source.size());
        for (size_t r = 0; r < source.size(); ++r) out[r] = in[source[r]];
    };
    if (uvs) gather(vuvs, mesh.uvs);
    if (colors) gather(vcolors, mesh.colors);
    if (normals) gather(vnormals, mesh.normals);
    for (glm::uvec3& t : mesh.triangles) t = glm::uvec3(remap[t.x], remap[t.y], remap[t.z]);
    for (glm::uvec2& l : mesh.line_segments) l = glm::uvec2(remap[l.x], remap[l.y]);
    mesh.positions.swap(positions);
    mesh.uvs.swap(vuvs);
    mesh.colors.swap(vcolors);
    mesh.normals.swap(vnormals);
    mesh.welded = true;
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
    const std::string ext = lower_ascii(std::filesystem::path(path).extension().string());
    const bool gltf = ext == ".gltf" || ext == ".glb" || ext == ".vrm";
    if (!options.pose.is_rest() && (!gltf || path.starts_with(kBuiltin)))
        throw InputError(path, "only glTF, GLB and VRM files have animations, morph targets and expressions");
    if (path.starts_with(kBuiltin)) {
        Mesh mesh = builtin::by_name(path.substr(kBuiltin.size()));
        if (options.compute_normals) geometry::ensure_vertex_normals(mesh, options.normal_weighting);
        return mesh;
    }

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
    } else if (gltf) {
        mesh = io::read_gltf(path, options.pose);
    } else if (io::assimp_reads(ext)) {
        mesh = io::read_with_assimp(path);
    } else {
        const bool assimp = !io::assimp_extensions().empty();
        throw InputError(
            path, (ext.empty() ? std::string("no file extension") : "unknown file extension " + io::quote_token(ext)) +
                      " (supported: .obj .stl .ply .off .gltf .glb .vrm" +
                      (assimp ? ", and through assimp .fbx .dae .3ds .blend .x and more)" : ")"));
    }

    validate(mesh, path);
    // Not for OBJ, glTF or assimp's formats with per-corner normals or uvs: those vertices are
    // split on purpose (hard edges, texture seams; the renderer welds positions itself where
    // lines need it). STL, PLY and OFF store one attribute set per vertex.
    const bool per_vertex_format = ext == ".stl" || ext == ".ply" || ext == ".off";
    bool split_on_purpose = !per_vertex_format && (!mesh.normals.empty() || !mesh.uvs.empty());
    if (soup || (!split_on_purpose && shares_no_vertex(mesh))) {
        // Per-corner normals of a soup are facet normals; after merging, the first one of each
        // cluster would win, so recompute smooth ones instead.
        mesh.normals.clear();
        weld_keeping_attributes(mesh, options.weld_epsilon);
    }
    // Duplicates (same or opposite winding) z-fight into speckles and make crease lines where a
    // face meets its own reverse. Compared on welded indices, before normals (a reversed copy
    // would cancel its original's contribution).
    if (options.drop_duplicate_faces) {
        const size_t dropped = geometry::drop_duplicate_faces(mesh);
        if (dropped > 0)
            mesh.warnings.push_back(path + ": dropped " + std::to_string(dropped) + " duplicate face" +
                                    (dropped == 1 ? "" : "s") + " (same vertices as an earlier face, either winding)");
    }
    if (options.compute_normals) {
        const bool file_normals = geometry::normals_are_sane(mesh);
        if (file_normals || !(options.smooth_angle < 180.0f) || options.normal_weighting != NormalWeighting::Angle) {
            geometry::ensure_vertex_normals(mesh, options.normal_weighting);
            if (!file_normals) geometry::auto_smooth(mesh, options.smooth_angle, options.normal_weighting);
        } else {
            // Auto-smooth reads the face normals the vertex normals are summed from: made once.
            const std::vector<glm::vec3> fn = geometry::face_normals(mesh);
            mesh.normals = geometry::angle_weighted_vertex_normals(mesh, fn);
            geometry::auto_smooth(mesh, options.smooth_angle, options.normal_weighting, fn);
        }
    } else if (!mesh.normals.empty() && !geometry::normals_are_sane(mesh))
        mesh.normals.clear();  // empty means "compute": better than passing NaNs on
    return mesh;
}

std::vector<std::string> builtin_model_names() { return builtin::names(); }

std::string readable_extensions() {
    // Asked by every command's --help text at start-up: assimp's importer list is built once.
    static const std::string list = [] {
        std::string out = ".obj .stl .ply .off .gltf .glb .vrm";
        const std::string native = out + " ";
        std::istringstream others(io::assimp_extensions());
        for (std::string ext; others >> ext;)
            if (native.find(lower_ascii(ext) + " ") == std::string::npos) out += " " + lower_ascii(ext);
        return out;
    }();
    return list;
}

namespace io {

bool format_is_soup(const std::string& extension) {
    std::string ext = lower_ascii(extension);
    if (ext.starts_with('.')) ext.erase(0, 1);
    return ext == "stl";
}

}  // namespace io
}  // namespace inkshade
