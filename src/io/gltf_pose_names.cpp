#include "io/gltf_pose_names.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <algorithm>

#include "inkshade/error.hpp"
#include "io/gltf_morph_targets.hpp"
#include "io/vrm_expressions.hpp"
#include "io/vrm_spring_bones.hpp"

namespace inkshade::io {

namespace {

// The time of the animation's last keyframe over the channels posing reads, as three.js's
// AnimationClip.resetDuration takes it (from 0, whatever the first key's time).
std::optional<float> duration(const tinygltf::Animation& animation, const GltfFloatReader& reader) {
    float end = 0.0f;
    try {
        for (const tinygltf::AnimationChannel& channel : animation.channels) {
            const std::string& path = channel.target_path;
            if (path != "translation" && path != "rotation" && path != "scale" && path != "weights") continue;
            if (channel.sampler < 0 || size_t(channel.sampler) >= animation.samplers.size()) return std::nullopt;
            int components = 0;
            const std::vector<float> times =
                reader.floats(animation.samplers[size_t(channel.sampler)].input, "keyframe times", {1}, components);
            if (!times.empty()) end = std::max(end, *std::max_element(times.begin(), times.end()));
        }
    } catch (const InputError&) {
        return std::nullopt;
    }
    return end;
}

}  // namespace

FilePoseNames read_gltf_pose_names(const tinygltf::Model& model, const std::string& path,
                                   const GltfFloatReader& reader) {
    FilePoseNames names;
    for (const tinygltf::Animation& a : model.animations) names.animations.push_back({a.name, duration(a, reader)});
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const std::string& name : morph_target_names(mesh))
            if (!name.empty() &&
                std::find(names.morph_targets.begin(), names.morph_targets.end(), name) == names.morph_targets.end())
                names.morph_targets.push_back(name);
    std::vector<std::string> ignored;  // the pose already gave these warnings
    for (const VrmExpression& e : read_vrm_expressions(model, path, ignored))
        names.expressions.push_back({e.name, is_vrm_preset(e.name)});
    try {  // bad spring bones are the pose's error (GltfPose), not this listing's
        names.spring_joints = read_vrm_spring_bones(model, path, ignored).joints.size();
    } catch (const InputError&) {
    }
    return names;
}

}  // namespace inkshade::io
