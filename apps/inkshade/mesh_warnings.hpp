// What a load got past (a texture not found, skipped primitives): one line each on stderr.
#pragma once
#include "inkshade/mesh.hpp"

namespace inkshade::cli {

void print_mesh_warnings(const Mesh& mesh);

}  // namespace inkshade::cli
