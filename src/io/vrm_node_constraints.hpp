// VRMC_node_constraint 1.0 (roll, aim and rotation constraints on glTF nodes) as three-vrm 3.5.5's
// VRMNodeConstraintManager applies them after the humanoid, look-at and expressions: each
// constraint turns its destination node from its rest rotation towards a target the source node
// decides, by its weight (slerp), a constraint on a node another one reads running first.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "io/gltf_rest_pose.hpp"
#include "io/pose_nodes.hpp"

namespace tinygltf {
class Model;
}

namespace inkshade::io {

struct VrmNodeConstraint {
    enum class Kind { Roll, Aim, Rotation } kind = Kind::Rotation;
    int destination = -1, source = -1;
    glm::dvec3 axis{1.0, 0.0, 0.0};  // roll: rollAxis; aim: aimAxis (signed unit axis)
    double weight = 1.0;
};

// The file's constraints, in node order (three-vrm's VRMNodeConstraintLoaderPlugin: the
// extension must be in extensionsUsed, specVersion 1.0 or 1.0-beta; one of roll, aim, rotation
// per node). A constraint whose source is not a node is left out with a warning.
std::vector<VrmNodeConstraint> read_vrm_node_constraints(const tinygltf::Model& model, const std::string& path,
                                                         std::vector<std::string>& warnings);

// The order three-vrm evaluates them in (VRMNodeConstraintManager._processConstraint): each
// after the constraints on its source, the source's ancestors and, for aim, its destination's
// ancestors. Throws InputError(path, ...) for a circular dependency, as three-vrm throws.
std::vector<size_t> vrm_node_constraint_order(const std::vector<VrmNodeConstraint>& constraints,
                                              const std::vector<int>& parent, const std::string& path);

// Applies the constraints in `order` (VRMRollConstraint, VRMAimConstraint and
// VRMRotationConstraint.update), rest rotations from `rest`.
void apply_vrm_node_constraints(const std::vector<VrmNodeConstraint>& constraints, const std::vector<size_t>& order,
                                const GltfRestPose& rest, PoseNodes& nodes);

}  // namespace inkshade::io
