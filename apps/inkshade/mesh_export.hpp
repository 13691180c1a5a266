// `--export-mesh FILE.obj|FILE.ply` of `render` and `lines`: the mesh as framed, written with
// the command's other outputs (all or none).
#pragma once
#include <string>
#include <vector>

#include "inkshade/mesh.hpp"
#include "inkshade/scene.hpp"

namespace inkshade::cli {

class MeshExport {
public:
    // Checks the request's path before any work (InputError, exit 2); none: does nothing.
    explicit MeshExport(const SceneRequest& request);
    // Keeps the positions and triangles, before the mesh moves into the renderer or extractor.
    void keep(const Mesh& mesh);
    // Writes the file; when that fails, removes `written` (the command's other outputs) and throws.
    void write(const std::vector<std::string>& written) const;

private:
    std::string path_;
    Mesh mesh_;
};

}  // namespace inkshade::cli
