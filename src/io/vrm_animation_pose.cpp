#include "io/vrm_animation_pose.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <algorithm>

#include "inkshade/error.hpp"
#include "io/gltf_names.hpp"
#include "io/vrm_animation.hpp"
#include "io/vrm_humanoid.hpp"
#include "io/vrm_look_at.hpp"

namespace inkshade::io {

namespace {

// VRMHumanoidRig.update: every raw human bone from its normalized twin (identity where the clip
// has no rotation), the hips placed at the normalized hips' world position.
void pose_humanoid(const std::vector<VrmAnimationPose::RawBone>& raw, const NormalizedPose& normalized,
                   const GltfRestPose& rest, PoseNodes& nodes) {
    for (const VrmAnimationPose::RawBone& b : raw) {
        const auto it = normalized.rotations.find(b.name);
        const glm::dquat n = it == normalized.rotations.end() ? glm::dquat(1.0, 0.0, 0.0, 0.0) : it->second;
        nodes.set_rotation(b.node, raw_bone_rotation(b.parent_world, rest.rotation[b.node], n));
        if (b.name != "hips") continue;
        const glm::dvec3 world = normalized.hips_position.value_or(glm::dvec3(rest.world[b.node][3]));
        const int p = rest.parent[b.node];
        const glm::dmat4 parent_world = p < 0 ? glm::dmat4(1.0) : nodes.world(size_t(p));
        nodes.set_translation(b.node, glm::dvec3(glm::inverse(parent_world) * glm::dvec4(world, 1.0)));
    }
}

// The avatar's human bones in VRMHumanBoneList order, each with its parent's rest world rotation.
std::vector<VrmAnimationPose::RawBone> raw_bones(const VrmHumanoid& humanoid, const GltfRestPose& rest) {
    std::vector<VrmAnimationPose::RawBone> out;
    for (const auto& [bone, parent] : vrm_human_bones()) {
        const int node = humanoid.node(bone);
        if (node >= 0) out.push_back({bone, size_t(node), rest.parent_world_rotation(size_t(node))});
    }
    return out;
}

bool has_expression(const std::vector<VrmExpression>& expressions, const std::string& name) {
    return std::any_of(expressions.begin(), expressions.end(), [&](const VrmExpression& e) { return e.name == name; });
}

VrmHumanoid humanoid_of(const tinygltf::Model& model, const std::string& path, const std::string& animation,
                        std::vector<std::string>& warnings) {
    std::optional<VrmHumanoid> humanoid = read_vrm_humanoid(model, path, warnings);
    if (!humanoid)
        throw InputError(path,
                         "has no VRM humanoid, which the VRM animation '" + printable_name(animation) + "' needs");
    return std::move(*humanoid);
}

}  // namespace

VrmAnimationPose::VrmAnimationPose(const tinygltf::Model& model, const std::string& path, const std::string& animation,
                                   const GltfRestPose& rest, const std::vector<VrmExpression>& expressions,
                                   std::vector<std::string>& warnings)
    : path_(path),
      animation_(animation),
      rest_(rest),
      expressions_(expressions),
      humanoid_(humanoid_of(model, path, animation, warnings)),
      look_at_(read_vrm_look_at(model)),
      clip_(animation),
      raw_(raw_bones(humanoid_, rest)),
      hips_height_(rest.world[size_t(humanoid_.node("hips"))][3].y) {}

std::vector<NamedWeight> VrmAnimationPose::apply(double time, const std::vector<NamedWeight>& user, PoseNodes& nodes,
                                                 std::vector<std::string>* warnings) const {
    const VrmAnimationSample sample = clip_.sample(time);
    std::vector<std::string> skipped;
    pose_humanoid(raw_, retarget_vrm_animation(sample, humanoid_, hips_height_, skipped), rest_, nodes);

    std::vector<NamedWeight> weights;
    for (const NamedWeight& w : sample.expressions) {
        if (has_expression(expressions_, w.name))
            weights.push_back(w);
        else
            skipped.push_back("expression " + w.name);
    }
    if (warnings && !skipped.empty()) {
        std::string list;
        for (const std::string& s : skipped) list += (list.empty() ? "" : ", ") + printable_name(s);
        warnings->push_back(animation_ + ": the avatar " + path_ + " lacks " + list + "; left out");
    }
    weights.insert(weights.end(), user.begin(), user.end());

    // VRMLookAt.update: the clip's look-at rotation (or none: straight ahead) as yaw and pitch.
    if (!look_at_) return weights;
    const glm::dvec2 yaw_pitch = sample.look_at ? look_at_yaw_pitch(*sample.look_at) : glm::dvec2(0.0);
    if (look_at_->expression) {
        for (const NamedWeight& w : look_at_expression_weights(*look_at_, yaw_pitch))
            if (has_expression(expressions_, w.name)) weights.push_back(w);
    } else {
        for (const auto& [node, q] : look_at_eye_rotations(*look_at_, humanoid_, rest_, yaw_pitch))
            nodes.set_rotation(size_t(node), q);
    }
    return weights;
}

}  // namespace inkshade::io
