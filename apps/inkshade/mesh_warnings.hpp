// What a load got past (a texture not found, skipped primitives): one line each on stderr.
#pragma once
#include <string>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::cli {

void print_mesh_warnings(const Mesh& mesh);
// The same for other warnings ("FILE: problem"), such as Scene::apply_file_scene's.
void print_warnings(const std::vector<std::string>& warnings);

}  // namespace inkshade::cli
