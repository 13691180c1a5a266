// A .vrma on a VRM avatar, frame by frame, as three-vrm 3.5.5 poses it: the clip
// (createVRMAnimationClip) sampled into the normalized humanoid, then VRM.update's humanoid
// (VRMHumanoidRig.update: normalized -> raw bones) and look-at; the expression weights it returns
// go to the expression manager (apply_vrm_expressions).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "inkshade/io.hpp"
#include "io/gltf_rest_pose.hpp"
#include "io/pose_nodes.hpp"
#include "io/vrm_animation.hpp"
#include "io/vrm_expressions.hpp"
#include "io/vrm_humanoid.hpp"
#include "io/vrm_look_at.hpp"

namespace tinygltf {
class Model;
}

namespace inkshade::io {

// A .vrma on an avatar, read once and posed at any time (GltfPose at Pose::time, the spring
// bones at each step).
class VrmAnimationPose {
public:
    // Reads the avatar's humanoid and look-at and the .vrma `animation`. `path`, `rest` and
    // `expressions` (the avatar's) must outlive it. Throws InputError for an avatar without a VRM
    // humanoid and for a .vrma that cannot be read (naming that file).
    VrmAnimationPose(const tinygltf::Model& model, const std::string& path, const std::string& animation,
                     const GltfRestPose& rest, const std::vector<VrmExpression>& expressions,
                     std::vector<std::string>& warnings);

    // Poses `nodes` by the clip at `time` and returns the expression weights in the order they
    // are set: the clip's (for expressions the avatar has), then `user` (given after the clip's,
    // they win), then the look-at's (type expression, which three-vrm sets last). Human bones and
    // expressions the avatar lacks are skipped, as three-vrm skips them, with one line in
    // `warnings` (nullptr: none). Throws InputError for bad data in the .vrma.
    std::vector<NamedWeight> apply(double time, const std::vector<NamedWeight>& user, PoseNodes& nodes,
                                   std::vector<std::string>* warnings) const;

    // A human bone the avatar has, with its parent's rest world rotation (VRMHumanoidRig's P).
    struct RawBone {
        std::string name;
        size_t node = 0;
        glm::dquat parent_world{1.0, 0.0, 0.0, 0.0};
    };

private:
    const std::string& path_;
    std::string animation_;
    const GltfRestPose& rest_;
    const std::vector<VrmExpression>& expressions_;
    VrmHumanoid humanoid_;
    std::optional<VrmLookAt> look_at_;
    VrmAnimationClip clip_;
    std::vector<RawBone> raw_;  // in VRMHumanBoneList order
    double hips_height_ = 0.0;
};

}  // namespace inkshade::io
