#include "io/vrm_animation.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "inkshade/error.hpp"
#include "io/gltf_accessors.hpp"
#include "io/gltf_animation.hpp"
#include "io/gltf_container.hpp"
#include "io/gltf_names.hpp"
#include "io/gltf_rest_pose.hpp"
#include "io/gltf_scene_nodes.hpp"
#include "io/gltf_value_member.hpp"

namespace inkshade::io {

namespace {

// A `node` member: -1 when absent; a node the file does not have is an error (three-vrm would
// fail on it).
int node_of(const tinygltf::Value& object, const tinygltf::Model& model, const std::string& what,
            const std::string& path) {
    const tinygltf::Value& node = member(object, "node");
    if (!node.IsNumber()) return -1;
    const double d = node.GetNumberAsDouble();
    if (!(d >= 0.0 && d < double(model.nodes.size()) && d == std::floor(d))) {
        char number[32];
        std::snprintf(number, sizeof number, "%g", d);
        throw InputError(
            path, what + " is node " + number + " but the file has " + std::to_string(model.nodes.size()) + " nodes");
    }
    return int(d);
}

// The `node` members of an object of objects ({"hips": {"node": 3}, ...}) as name -> node.
std::map<std::string, int> node_map(const tinygltf::Value& object, const tinygltf::Model& model,
                                    const std::string& what, const std::string& path) {
    std::map<std::string, int> out;
    if (!object.IsObject()) return out;
    for (const std::string& name : object.Keys()) {
        const int node = node_of(object.Get(name), model, what + " '" + printable_name(name) + "'", path);
        if (node >= 0) out[name] = node;
    }
    return out;
}

// The VRMC_vrm_animation extension, checked as VRMAnimationLoaderPlugin does.
const tinygltf::Value& vrma_extension(const tinygltf::Model& model, const std::string& path) {
    const auto ext = model.extensions.find("VRMC_vrm_animation");
    const bool used = std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "VRMC_vrm_animation") !=
                      model.extensionsUsed.end();
    if (ext == model.extensions.end() || !used || !ext->second.IsObject())
        throw InputError(path, "is not a VRM animation (no VRMC_vrm_animation extension)");
    const tinygltf::Value& version = member(ext->second, "specVersion");
    if (version.IsString() && version.Get<std::string>() != "1.0" && version.Get<std::string>() != "1.0-draft")
        throw InputError(path, "unknown VRMC_vrm_animation specVersion '" + printable_name(version.Get<std::string>()) +
                                   "' (1.0 is read)");
    if (model.animations.empty()) throw InputError(path, "the VRM animation has no animation");
    return ext->second;
}

// A human bone of the .vrma with what turns its animated rotation q into the normalized
// humanoid's terms, B x q x A^-1: A the bone's rest world rotation, B that of its nearest
// human-bone ancestor the .vrma has (or of the hips' parent) (three-vrm-animation
// VRMAnimationLoaderPlugin._parseAnimation). Computed once: the clip is sampled at every step.
struct NormalizingBone {
    std::string name;
    size_t node = 0;
    glm::dquat before{1.0, 0.0, 0.0, 0.0}, after{1.0, 0.0, 0.0, 0.0};  // B and A^-1
};

std::vector<NormalizingBone> normalizing_bones(const std::map<std::string, int>& bones, const GltfRestPose& rest) {
    std::map<std::string, std::string> parent_of;
    for (const auto& [bone, parent] : vrm_human_bones()) parent_of[bone] = parent;
    const auto hips = bones.find("hips");
    const glm::dquat hips_parent =
        hips == bones.end() ? glm::dquat(1.0, 0.0, 0.0, 0.0) : rest.parent_world_rotation(size_t(hips->second));
    std::vector<NormalizingBone> out;
    for (const auto& [bone, node] : bones) {
        std::string parent = parent_of.count(bone) ? parent_of[bone] : "";
        while (!parent.empty() && !bones.count(parent)) parent = parent_of[parent];
        const glm::dquat b = parent.empty() ? hips_parent : rotation_of(rest.world[size_t(bones.at(parent))]);
        out.push_back({bone, size_t(node), b, glm::inverse(rotation_of(rest.world[size_t(node)]))});
    }
    return out;
}

// createVRMAnimationHumanoidTracks and _parseAnimation build new tracks for the humanoid
// rotations and the expression weights, which take three.js's default interpolation: STEP keys
// of those channels are interpolated linearly there, and so here.
void step_as_linear(tinygltf::Model& model, const std::map<std::string, int>& bones,
                    const std::map<std::string, int>& expressions) {
    auto is_bone = [&](int node) {
        for (const auto& [name, n] : bones)
            if (n == node) return true;
        return false;
    };
    auto is_expression = [&](int node) {
        for (const auto& [name, n] : expressions)
            if (n == node) return true;
        return false;
    };
    tinygltf::Animation& animation = model.animations[0];
    for (const tinygltf::AnimationChannel& c : animation.channels) {
        const bool rebuilt = (c.target_path == "rotation" && is_bone(c.target_node)) ||
                             (c.target_path == "translation" && is_expression(c.target_node));
        if (rebuilt && c.sampler >= 0 && size_t(c.sampler) < animation.samplers.size() &&
            animation.samplers[size_t(c.sampler)].interpolation == "STEP")
            animation.samplers[size_t(c.sampler)].interpolation = "LINEAR";
    }
}

}  // namespace

bool is_vrma_path(const std::string& animation) {
    if (animation.size() < 5) return false;
    std::string ext = animation.substr(animation.size() - 5);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".vrma";
}

struct VrmAnimationClip::Data {
    std::string path;
    tinygltf::Model model;
    std::map<std::string, int> bones, expressions;  // human bone / expression -> node
    int look_at = -1;
    std::vector<int> parent;
    GltfRestPose rest;
    std::vector<NormalizingBone> normalizing;
};

VrmAnimationClip::VrmAnimationClip(const std::string& path) {
    auto d = std::make_unique<Data>();
    d->path = path;
    tinygltf::Model& model = d->model;
    load_gltf_model(path, model);
    const tinygltf::Value& ext = vrma_extension(model, path);
    d->bones = node_map(member(member(ext, "humanoid"), "humanBones"), model, "humanoid bone", path);
    for (const char* group : {"preset", "custom"})
        for (const auto& [name, node] : node_map(member(member(ext, "expressions"), group), model, "expression", path))
            d->expressions.emplace(name, node);
    d->look_at = node_of(member(ext, "lookAt"), model, "lookAt", path);

    d->parent.assign(model.nodes.size(), -1);
    for (size_t p = 0; p < model.nodes.size(); ++p)
        for (int c : model.nodes[p].children)
            if (c >= 0 && size_t(c) < d->parent.size() && d->parent[size_t(c)] < 0) d->parent[size_t(c)] = int(p);
    d->rest = gltf_rest_pose(d->parent, [&](size_t i) { return gltf_node_transform(model.nodes[i], i, path); });
    d->normalizing = normalizing_bones(d->bones, d->rest);
    step_as_linear(model, d->bones, d->expressions);
    data_ = std::move(d);
}

VrmAnimationClip::~VrmAnimationClip() = default;
VrmAnimationClip::VrmAnimationClip(VrmAnimationClip&&) noexcept = default;
VrmAnimationClip& VrmAnimationClip::operator=(VrmAnimationClip&&) noexcept = default;

VrmAnimationSample VrmAnimationClip::sample(double time) const {
    const Data& d = *data_;
    const GltfAccessorReader reader(d.model, d.path);
    const std::vector<AnimatedNode> animated = sample_gltf_animation(d.model, 0, time, reader);

    VrmAnimationSample out;
    for (const NormalizingBone& b : d.normalizing)
        if (animated[b.node].rotation) out.rotations[b.name] = b.before * *animated[b.node].rotation * b.after;
    if (const auto hips = d.bones.find("hips"); hips != d.bones.end()) {
        const size_t node = size_t(hips->second);
        out.rest_hips_height = d.rest.world[node][3].y;
        if (animated[node].translation) {
            if (!(out.rest_hips_height > 0.0))
                throw InputError(d.path, "the rest pose's hips are at height " + std::to_string(out.rest_hips_height) +
                                             " (a VRM animation's rest pose stands above y = 0)");
            const glm::dmat4 m = d.parent[node] < 0 ? glm::dmat4(1.0) : d.rest.world[size_t(d.parent[node])];
            out.hips = glm::dvec3(m * glm::dvec4(*animated[node].translation, 1.0));
        }
    }
    for (const auto& [name, node] : d.expressions)
        if (animated[size_t(node)].translation)
            out.expressions.push_back({name, float(animated[size_t(node)].translation->x)});
    if (d.look_at >= 0 && animated[size_t(d.look_at)].rotation) out.look_at = *animated[size_t(d.look_at)].rotation;
    return out;
}

NormalizedPose retarget_vrm_animation(const VrmAnimationSample& sample, const VrmHumanoid& humanoid,
                                      double avatar_hips_height, std::vector<std::string>& skipped) {
    NormalizedPose pose;
    // createVRMAnimationHumanoidTracks: VRM 0.x avatars face -z, so x and z change sign.
    const glm::dvec3 flip = humanoid.v0 ? glm::dvec3(-1.0, 1.0, -1.0) : glm::dvec3(1.0);
    for (const auto& [bone, q] : sample.rotations) {
        if (humanoid.node(bone) < 0) {
            skipped.push_back(bone);
            continue;
        }
        pose.rotations[bone] = glm::dquat(q.w, flip.x * q.x, q.y, flip.z * q.z);
    }
    if (sample.hips && humanoid.node("hips") >= 0)
        pose.hips_position = *sample.hips * flip * (avatar_hips_height / sample.rest_hips_height);
    return pose;
}

}  // namespace inkshade::io
