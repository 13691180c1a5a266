#include "mesh_warnings.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace inkshade::cli {

void print_mesh_warnings(const Mesh& mesh) { print_warnings(mesh.warnings); }

void print_warnings(const std::vector<std::string>& warnings) {
    for (std::string line : warnings) {
        std::replace(line.begin(), line.end(), '\n', ' ');  // one line each, whatever the file held
        std::fprintf(stderr, "inkshade: warning: %s\n", line.c_str());
    }
}

}  // namespace inkshade::cli
