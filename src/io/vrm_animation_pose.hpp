// One frame of a .vrma on a VRM avatar as three-vrm 3.5.5 poses it: the clip
// (createVRMAnimationClip) sampled into the normalized humanoid, then VRM.update's humanoid
// (VRMHumanoidRig.update: normalized -> raw bones) and look-at; the expression weights it returns
// go to the expression manager (apply_vrm_expressions).
#pragma once
#include <string>
#include <vector>

#include "inkshade/io.hpp"
#include "io/gltf_rest_pose.hpp"
#include "io/pose_nodes.hpp"
#include "io/vrm_expressions.hpp"

namespace tinygltf {
class Model;
}

namespace inkshade::io {

// Poses `nodes` of the avatar `model` by the .vrma pose.animation at pose.time and returns the
// expression weights in the order they are set: the clip's (for expressions the avatar has),
// then pose.expressions (given after the clip's, they win), then the look-at's (type
// expression, which three-vrm sets last). Human bones and expressions the avatar lacks are
// skipped with one warning, as three-vrm skips them. Throws InputError for an avatar without a
// VRM humanoid and for a bad .vrma (naming that file).
std::vector<NamedWeight> apply_vrm_animation(const tinygltf::Model& model, const std::string& path, const Pose& pose,
                                             const GltfRestPose& rest, const std::vector<VrmExpression>& expressions,
                                             PoseNodes& nodes, std::vector<std::string>& warnings);

}  // namespace inkshade::io
