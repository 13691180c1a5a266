// `inkshade info MODEL`: facts about a mesh as loaded, duplicate faces kept (they are counted).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <set>

#include "commands.hpp"
#include "geometry/mesh_stats.hpp"
#include "inkshade/io.hpp"
#include "mesh_warnings.hpp"

namespace inkshade::cli {

namespace {

// Distinct images among the materials' textures (materials may share one).
size_t texture_count(const Mesh& mesh) {
    std::set<const Texture*> textures;
    for (const Material& m : mesh.materials)
        if (m.texture) textures.insert(m.texture.get());
    return textures.size();
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
        geometry::MeshStats s = geometry::mesh_stats(mesh);
        BoundingBox b = mesh.bounds();
        std::printf("model:                %s\n", model->c_str());
        std::printf("vertices:             %zu\n", s.vertices);
        std::printf("triangles:            %zu\n", s.triangles);
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
        std::printf("load time:            %.1f ms\n", load_ms);
        return 0;
    };
}

}  // namespace inkshade::cli
