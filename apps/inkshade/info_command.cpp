// `inkshade info MODEL`: facts about a mesh as loaded, duplicate faces kept (they are counted).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <string>

#include "commands.hpp"
#include "inkshade/io.hpp"
#include "inkshade/mesh_stats.hpp"
#include "io/gltf_names.hpp"
#include "mesh_warnings.hpp"

namespace inkshade::cli {

namespace {

// Distinct images among the materials' textures, base colour and MToon maps (materials may
// share one).
size_t texture_count(const Mesh& mesh) {
    std::set<const Texture*> textures;
    for (const Material& m : mesh.materials) {
        if (m.texture) textures.insert(m.texture.get());
        for (const auto& [slot, t] : m.mtoon_textures)
            if (t) textures.insert(t.get());
    }
    return textures.size();
}

// "0.1", or `absent` for a value the file leaves out (a far plane, range, aspect ratio).
std::string number_or(const std::optional<float>& v, const char* absent) {
    if (!v) return absent;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", *v);
    return buf;
}

// A vector as "x y z", rounding away the float noise of rotations (-2.2e-16 reads 0).
std::string vec3_text(const glm::vec3& v) {
    char buf[96];
    const auto clean = [](float x) { return std::abs(x) < 1e-6f ? 0.0f : x; };
    std::snprintf(buf, sizeof buf, "%g %g %g", clean(v.x), clean(v.y), clean(v.z));
    return buf;
}

// One line per camera, as `--camera` takes them: index, name, projection, placement.
void print_cameras(const Mesh& mesh) {
    std::printf("cameras:              %zu\n", mesh.cameras.size());
    for (size_t i = 0; i < mesh.cameras.size(); ++i) {
        const FileCamera& c = mesh.cameras[i];
        const NodePlacement& p = c.placement;
        if (c.orthographic)
            std::printf("  %zu '%s': orthographic, xmag %g, ymag %g", i, c.name.c_str(), c.xmag, c.ymag);
        else
            std::printf("  %zu '%s': perspective, yfov %g deg, aspect %s", i, c.name.c_str(), c.yfov_degrees,
                        number_or(c.aspect_ratio, "of the image").c_str());
        std::printf(", znear %g, zfar %s; at %s looking %s, up %s\n", c.znear, number_or(c.zfar, "infinite").c_str(),
                    vec3_text(p.position).c_str(), vec3_text(p.forward).c_str(), vec3_text(p.up).c_str());
    }
}

// One line per light (KHR_lights_punctual), in the extension's units.
void print_lights(const Mesh& mesh) {
    std::printf("lights:               %zu\n", mesh.lights.size());
    for (size_t i = 0; i < mesh.lights.size(); ++i) {
        const FileLight& l = mesh.lights[i];
        const NodePlacement& p = l.placement;
        const char* type = l.type == FileLightType::Directional ? "directional"
                           : l.type == FileLightType::Point     ? "point"
                                                                : "spot";
        std::printf("  %zu '%s': %s, colour %s, intensity %g %s", i, l.name.c_str(), type, vec3_text(l.color).c_str(),
                    l.intensity, l.type == FileLightType::Directional ? "lux" : "cd");
        if (l.type != FileLightType::Directional)
            std::printf(", range %s, at %s", number_or(l.range, "infinite").c_str(), vec3_text(p.position).c_str());
        if (l.type == FileLightType::Spot)
            std::printf(", cone %g..%g deg", glm::degrees(l.inner_cone_angle), glm::degrees(l.outer_cone_angle));
        if (l.type != FileLightType::Point) std::printf(", shining %s", vec3_text(p.forward).c_str());
        std::printf("\n");
    }
    for (const std::string& unusable : mesh.unusable_lights) std::printf("  not usable: %s\n", unusable.c_str());
}

// The names --animation, --morph and --expression take (glTF/VRM), one a line; a kind the file
// has none of is left out.
void print_pose_names(const FilePoseNames& names) {
    if (!names.animations.empty()) {
        std::printf("animations:           %zu\n", names.animations.size());
        for (size_t i = 0; i < names.animations.size(); ++i) {
            const FileAnimation& a = names.animations[i];
            std::printf("  %zu '%s': ", i, io::printable_name(a.name).c_str());
            if (a.duration)
                std::printf("%g s\n", *a.duration);
            else
                std::printf("duration unknown (its keyframe times cannot be read)\n");
        }
    }
    if (!names.morph_targets.empty()) {
        std::printf("morph targets:        %zu\n", names.morph_targets.size());
        for (const std::string& m : names.morph_targets) std::printf("  '%s'\n", io::printable_name(m).c_str());
    }
    if (!names.expressions.empty()) {
        std::printf("expressions:          %zu\n", names.expressions.size());
        for (const FileExpression& e : names.expressions)
            std::printf("  '%s' (%s)\n", io::printable_name(e.name).c_str(), e.preset ? "preset" : "custom");
    }
    if (names.spring_joints > 0) std::printf("spring bone joints:   %zu\n", names.spring_joints);
}

}  // namespace

Command add_info_command(CLI::App& app) {
    auto model = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("info", "print facts about a mesh (counts, bounds, topology)");
    cmd->add_option("MODEL", *model, "mesh file (" + readable_extensions() + ") or builtin:NAME")->required();
    return [model] {
        auto start = std::chrono::steady_clock::now();
        LoadOptions as_in_file;  // count the file's duplicate faces rather than drop them
        as_in_file.drop_duplicate_faces = false;
        Mesh mesh = load_mesh(*model, as_in_file);
        print_mesh_warnings(mesh);
        double load_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        MeshStats s = mesh_stats(mesh);
        BoundingBox b = mesh.bounds();
        std::printf("model:                %s\n", model->c_str());
        std::printf("vertices:             %zu\n", s.vertices);
        std::printf("triangles:            %zu\n", s.triangles);
        // OBJ `l`, glTF LINES / LINE_STRIP / LINE_LOOP: drawn by the `loose` line type.
        if (!mesh.line_segments.empty()) std::printf("loose line segments:  %zu\n", mesh.line_segments.size());
        std::printf("edges:                %zu\n", s.edges);
        std::printf("bounding box min:     %g %g %g\n", b.min.x, b.min.y, b.min.z);
        std::printf("bounding box max:     %g %g %g\n", b.max.x, b.max.y, b.max.z);
        std::printf("bounding box size:    %g %g %g (diagonal %g)\n", b.max.x - b.min.x, b.max.y - b.min.y,
                    b.max.z - b.min.z, b.diagonal());
        std::printf("welded:               %s\n", mesh.welded ? "yes" : "no");
        std::printf("boundary edges:       %zu\n", s.boundary_edges);
        std::printf("non-manifold edges:   %zu\n", s.non_manifold_edges);
        std::printf("degenerate faces:     %zu\n", s.degenerate_faces);
        std::printf("duplicate faces:      %zu\n", s.duplicate_faces);
        std::printf("components:           %zu\n", s.components);
        std::printf("euler characteristic: %ld\n", s.euler_characteristic);
        std::printf("materials:            %zu\n", mesh.materials.size());
        std::printf("textures:             %zu\n", texture_count(mesh));
        std::printf("texture coordinates:  %s\n", mesh.uvs.empty() ? "no" : "yes");
        std::printf("vertex colours:       %s\n", mesh.colors.empty() ? "no" : "yes");
        const size_t unlit = size_t(
            std::count_if(mesh.materials.begin(), mesh.materials.end(), [](const Material& m) { return m.unlit; }));
        if (unlit > 0) std::printf("unlit materials:      %zu\n", unlit);
        print_cameras(mesh);
        print_lights(mesh);
        print_pose_names(mesh.pose_names);
        std::printf("load time:            %.1f ms\n", load_ms);
        return 0;
    };
}

}  // namespace inkshade::cli
