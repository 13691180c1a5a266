#include "io/vrm_spring_pose.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include "io/gltf_animation.hpp"
#include "io/node_trs_frame.hpp"
#include "io/vrm_animation.hpp"
#include "io/vrm_spring_bones.hpp"

namespace inkshade::io {

NodeTrs file_node_trs(const tinygltf::Node& node, const glm::dmat4& file) {
    NodeTrs n;
    if (!node.matrix.empty()) {  // section 3.5.2: decomposed, as three.js's GLTFLoader does
        glm::dvec3 skew;
        glm::dvec4 perspective;
        glm::decompose(file, n.s, n.r, n.t, skew, perspective);
        return n;
    }
    if (node.translation.size() == 3) n.t = glm::make_vec3(node.translation.data());
    if (node.rotation.size() == 4)
        n.r = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    if (node.scale.size() == 3) n.s = glm::make_vec3(node.scale.data());
    const double len = glm::length(n.r);
    n.r = len > 0.0 ? n.r / len : glm::dquat(1.0, 0.0, 0.0, 0.0);
    return n;
}

std::vector<std::optional<glm::dquat>> pose_spring_bones(
    const tinygltf::Model& model, const std::string& path, const Pose& pose, const GltfFloatReader& reader,
    glm::dmat4 (*file_transform)(const tinygltf::Node&, size_t, const std::string&), const std::vector<int>& parent,
    const VrmStepsAt& vrm_steps, std::vector<std::string>& warnings) {
    if (!pose.spring_bones) return {};
    const SpringBones bones = read_vrm_spring_bones(model, path, warnings);
    if (bones.empty()) return {};
    std::vector<NodeTrs> rest;
    for (size_t i = 0; i < model.nodes.size(); ++i)
        rest.push_back(file_node_trs(model.nodes[i], file_transform(model.nodes[i], i, path)));
    const bool glTF_animation = !pose.animation.empty() && !is_vrma_path(pose.animation);
    const int animation = glTF_animation ? find_gltf_animation(model, pose.animation, path) : -1;
    // Each step's frame as a three.js app has it before vrm.update's springs: mixer.update (the
    // glTF animation's values), then the humanoid, look-at and node constraints.
    const NodePoseAt pose_at = [&](double time, std::vector<NodeTrs>& nodes) {
        if (animation >= 0) {
            const std::vector<AnimatedNode> a = sample_gltf_animation(model, animation, time, reader);
            for (size_t i = 0; i < nodes.size() && i < a.size(); ++i) {
                if (a[i].translation) nodes[i].t = *a[i].translation;
                if (a[i].scale) nodes[i].s = *a[i].scale;
                if (!a[i].rotation) continue;
                const double len = glm::length(*a[i].rotation);
                nodes[i].r = len > 0.0 ? *a[i].rotation / len : glm::dquat(1.0, 0.0, 0.0, 0.0);
                nodes[i].rotation_animated = true;
            }
        }
        if (!vrm_steps) return;
        NodeTrsFrame frame(nodes, parent);
        vrm_steps(time, frame);
    };
    return simulate_spring_bones(bones, parent, rest, pose_at, double(pose.time), path);
}

}  // namespace inkshade::io
