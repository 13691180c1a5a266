// The node hierarchy of a glTF's scene (glTF 2.0 section 3.5): each node's own transform as the
// file writes it (matrix or T x R x S, checked), and the scene walked depth-first into mesh
// instances and the nodes that may carry a camera or a light, each with its world transform
// in the pose read_gltf reads (GltfPose supplies the local transforms).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "io/gltf_cameras_lights.hpp"

namespace tinygltf {
class Model;
struct Node;
}  // namespace tinygltf

namespace inkshade::io {

class GltfPose;

// The file's local transform of node `index` (GltfPose::FileTransform). Throws
// InputError(path, ...) for a matrix, translation, rotation or scale of the wrong size or not
// finite.
glm::dmat4 gltf_node_transform(const tinygltf::Node& node, size_t index, const std::string& path);

// A mesh placed by a node.
struct GltfInstance {
    int node;
    int mesh;
    glm::dmat4 transform;
};

// What the scene's nodes hold, in depth-first order.
struct GltfSceneNodes {
    std::vector<GltfInstance> meshes;
    std::vector<PlacedNode> cameras_and_lights;  // nodes with a camera or a KHR_lights_punctual light
};

// Every mesh instance of the default scene (or the first scene, or every root node when there
// is none) with its world transform, and the nodes that may carry a camera or a light. The
// hierarchy must be a tree (section 3.5.3): a node reached twice (a cycle or two parents) is an
// error, never a hang. Throws InputError(path, ...).
GltfSceneNodes gltf_scene_nodes(const tinygltf::Model& model, const std::string& path, const GltfPose& pose);

}  // namespace inkshade::io
