// What a load got past (a texture not found, skipped primitives): one line each on stderr.
#pragma once
#include <string>
#include <vector>

#include "inkshade/mesh.hpp"
#include "inkshade/scene.hpp"

namespace inkshade::cli {

void print_mesh_warnings(const Mesh& mesh);
// The same for other warnings ("FILE: problem"), such as Scene::apply_file_scene's.
void print_warnings(const std::vector<std::string>& warnings);

// The scene's model loaded as it asks (Scene::load_options), with the file's camera and light it
// asks for taken (Scene::apply_file_scene) and every warning printed; `milliseconds` is the
// wall time of all that, for --timing.
Mesh load_scene_model(Scene& scene, double& milliseconds);

}  // namespace inkshade::cli
