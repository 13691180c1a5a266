// MeshExport (mesh_export.hpp).
#include "mesh_export.hpp"

#include <filesystem>

#include "inkshade/error.hpp"
#include "inkshade/mesh_writer.hpp"
#include "output_path.hpp"

namespace inkshade::cli {

MeshExport::MeshExport(const SceneRequest& request) : path_(request.export_mesh) {
    if (path_.empty()) return;
    if (!is_mesh_export_path(path_))
        throw InputError("--export-mesh: expected FILE.obj or FILE.ply, got '" + path_ + "'");
    check_output_path("--export-mesh", path_);
}

void MeshExport::keep(const Mesh& mesh) {
    if (path_.empty()) return;
    mesh_.positions = mesh.positions;
    mesh_.triangles = mesh.triangles;
}

void MeshExport::write(const std::vector<std::string>& written) const {
    if (path_.empty()) return;
    try {
        write_mesh(path_, mesh_);
    } catch (...) {
        std::error_code ec;
        for (const std::string& file : written) std::filesystem::remove(file, ec);
        throw;
    }
}

}  // namespace inkshade::cli
