#include "mesh_warnings.hpp"

#include <algorithm>
#include <chrono>
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

Mesh load_scene_model(Scene& scene, double& milliseconds) {
    const auto start = std::chrono::steady_clock::now();
    Mesh mesh = load_mesh(scene.model, scene.load_options());
    print_mesh_warnings(mesh);
    print_warnings(scene.apply_file_scene(mesh));
    milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return mesh;
}

}  // namespace inkshade::cli
