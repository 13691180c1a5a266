// export-mesh in a batch: each model's mesh as framed, once per model and pose, beside the
// model's output directory (OUTPUT_DIR/NAME.mesh.obj or .ply; batch::mesh_file_stem).
#pragma once
#include <string>
#include <vector>

#include "inkshade/batch.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::batch {

// Writes the mesh files the jobs `indices` of `jobs` ask for (each file once), atomically.
// Throws RuntimeError("FILE: reason").
void write_mesh_files(const std::string& output_dir, const std::vector<BatchJob>& jobs,
                      const std::vector<size_t>& indices, const Mesh& mesh);

}  // namespace inkshade::batch
