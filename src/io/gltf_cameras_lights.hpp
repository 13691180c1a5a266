// The cameras (glTF 2.0 section 3.10) and KHR_lights_punctual lights of a glTF's scene, read
// by read_gltf from the nodes that carry them. A bad camera or light is a warning and is left
// out: it never costs the mesh.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "inkshade/mesh.hpp"

namespace tinygltf {
class Model;
}

namespace inkshade::io {

// A node of the scene with its global transform.
struct PlacedNode {
    int node;
    glm::dmat4 transform;
};

// Appends the camera of each node in `nodes` that has one, in order, to mesh.cameras (and
// problems to mesh.warnings).
void add_gltf_cameras(const tinygltf::Model& model, const std::vector<PlacedNode>& nodes, const std::string& path,
                      Mesh& mesh);

// Appends the KHR_lights_punctual light of each node in `nodes` that has one to mesh.lights.
void add_gltf_lights(const tinygltf::Model& model, const std::vector<PlacedNode>& nodes, const std::string& path,
                     Mesh& mesh);

}  // namespace inkshade::io
