// Writing a mesh back out (`--export-mesh`): its triangles in the world coordinates of every
// camera Inkshade frames for it, for re-projection, point clouds and splatting initialisation.
#pragma once
#include <string>

#include "inkshade/mesh.hpp"

namespace inkshade {

// Writes the mesh's positions and triangles to `path`, by its extension (any case): .obj
// (text, the shortest text that reads back to each float) or .ply (binary little-endian, float
// x, y, z; int faces). The coordinates are those load_mesh gave, the world of the camera files,
// batch metadata and transforms.json, so projecting a vertex with their matrices lands on the
// image. Written atomically. Throws InputError for another extension, RuntimeError("PATH:
// reason") when the file cannot be written.
void write_mesh(const std::string& path, const Mesh& mesh);

// Whether `path` ends with .obj or .ply (any case), as write_mesh takes it.
bool is_mesh_export_path(const std::string& path);

}  // namespace inkshade
