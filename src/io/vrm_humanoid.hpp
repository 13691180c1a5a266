// The humanoid of a VRM avatar (VRM 1.0 VRMC_vrm.humanoid.humanBones, VRM 0.x
// VRM.humanoid.humanBones) and how three-vrm 3.5.5 poses it. Each human bone has a "normalized"
// twin whose rest rotation is the identity in world axes (VRMHumanoidRig); an animation rotates
// the normalized bones (and moves the normalized hips), and VRMHumanoidRig.update turns that into
// the raw bones' local transforms.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "io/gltf_rest_pose.hpp"

namespace tinygltf {
class Model;
}

namespace inkshade::io {

// Every human bone name in three-vrm's VRMHumanBoneList order, with its parent bone
// (VRMHumanBoneParentMap; empty for hips).
const std::vector<std::pair<std::string, std::string>>& vrm_human_bones();

struct VrmHumanoid {
    bool v0 = false;                   // a VRM 0.x avatar (three-vrm's metaVersion "0")
    std::map<std::string, int> bones;  // human bone (VRM 1.0 names) -> node

    int node(const std::string& bone) const {
        const auto it = bones.find(bone);
        return it == bones.end() ? -1 : it->second;
    }
};

// The avatar's humanoid: VRM 1.0's when the file has VRMC_vrm, else VRM 0.x's; nullopt for a
// file with neither. As three-vrm's VRMHumanoidLoaderPlugin: VRM 0.x / early 1.0 thumb names
// are renamed (thumbProximal -> thumbMetacarpal, ...), a bone whose node does not exist is left
// out with a warning, and a missing required bone (hips, spine, head, legs, arms, hands) is an
// InputError(path, ...).
std::optional<VrmHumanoid> read_vrm_humanoid(const tinygltf::Model& model, const std::string& path,
                                             std::vector<std::string>& warnings);

// A normalized pose: rotations of normalized bones (others keep the identity) and the
// normalized hips' world position (nullopt: its rest position).
struct NormalizedPose {
    std::map<std::string, glm::dquat> rotations;
    std::optional<glm::dvec3> hips_position;
};

// The raw local rotation three-vrm's VRMHumanoidRig.update gives `bone` (the humanoid has it)
// for a normalized rotation: P^-1 x N x P x R0, P the rest world rotation of the raw bone's
// parent, R0 its rest local rotation.
glm::dquat raw_bone_rotation(const VrmHumanoid& humanoid, const GltfRestPose& rest, const std::string& bone,
                             const glm::dquat& normalized);
// The same with P (`parent_world`) and R0 (`rest_local`) given.
inline glm::dquat raw_bone_rotation(const glm::dquat& parent_world, const glm::dquat& rest_local,
                                    const glm::dquat& normalized) {
    return glm::inverse(parent_world) * normalized * parent_world * rest_local;
}

}  // namespace inkshade::io
