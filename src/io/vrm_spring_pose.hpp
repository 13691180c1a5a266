// The spring bones of a glTF/VRM file in the pose LoadOptions::pose asks for: read
// (vrm_spring_bones.hpp) and simulated (spring_bone_simulation.hpp) from the file's pose at t = 0
// to Pose::time; at every step the glTF animation (if any) is sampled, then the VRM steps that
// three-vrm's VRM.update runs before its springs (a .vrma's humanoid and look-at, the node
// constraints) pose the frame; GltfPose turns the joints' nodes by the result in place of the
// file's and the animation's rotations.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "inkshade/io.hpp"
#include "io/gltf_accessors.hpp"
#include "io/pose_nodes.hpp"
#include "io/spring_bone_simulation.hpp"

namespace tinygltf {
class Model;
struct Node;
}  // namespace tinygltf

namespace inkshade::io {

// A node's T, R and S as three.js holds them: its own, or its matrix decomposed (`file` is its
// checked local matrix).
NodeTrs file_node_trs(const tinygltf::Node& node, const glm::dmat4& file);

// What three-vrm's VRM.update does to the nodes before the springs, at a time (GltfPose's .vrma
// and node constraints); empty: nothing.
using VrmStepsAt = std::function<void(double time, PoseNodes& nodes)>;

// The rotation of every node a spring bone joint turns (indexed by node; empty where none does,
// and all empty where the file has no spring bones or Pose::spring_bones is off). `parent[n]`:
// node n's parent, -1 for a root; `vrm_steps` runs at each step after the glTF animation.
// Throws InputError for bad spring bones (read_vrm_spring_bones, simulate_spring_bones) or a bad
// animation.
std::vector<std::optional<glm::dquat>> pose_spring_bones(
    const tinygltf::Model& model, const std::string& path, const Pose& pose, const GltfFloatReader& reader,
    glm::dmat4 (*file_transform)(const tinygltf::Node&, size_t, const std::string&), const std::vector<int>& parent,
    const VrmStepsAt& vrm_steps, std::vector<std::string>& warnings);

}  // namespace inkshade::io
