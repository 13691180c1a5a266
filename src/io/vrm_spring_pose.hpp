// The spring bones of a glTF/VRM file in the pose LoadOptions::pose asks for: read
// (vrm_spring_bones.hpp) and simulated (spring_bone_simulation.hpp) from the file's pose at t = 0
// to Pose::time, the animation (if any) sampled at every step; GltfPose turns the joints' nodes
// by the result in place of the file's and the animation's rotations.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "inkshade/io.hpp"
#include "io/gltf_accessors.hpp"
#include "io/spring_bone_simulation.hpp"

namespace tinygltf {
class Model;
struct Node;
}  // namespace tinygltf

namespace inkshade::io {

// A node's T, R and S as three.js holds them: its own, or its matrix decomposed (`file` is its
// checked local matrix).
NodeTrs file_node_trs(const tinygltf::Node& node, const glm::dmat4& file);

// The rotation of every node a spring bone joint turns (indexed by node; empty where none does,
// and all empty where the file has no spring bones or Pose::spring_bones is off). `parent[n]`:
// node n's parent, -1 for a root. Throws InputError for bad spring bones (read_vrm_spring_bones,
// simulate_spring_bones) or a bad animation.
std::vector<std::optional<glm::dquat>> pose_spring_bones(
    const tinygltf::Model& model, const std::string& path, const Pose& pose, const GltfFloatReader& reader,
    glm::dmat4 (*file_transform)(const tinygltf::Node&, size_t, const std::string&), const std::vector<int>& parent,
    std::vector<std::string>& warnings);

}  // namespace inkshade::io
