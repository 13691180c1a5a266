#include "io/gltf_pose.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "inkshade/error.hpp"
#include "io/gltf_morph_targets.hpp"
#include "io/gltf_names.hpp"
#include "io/gltf_skinning.hpp"
#include "io/vrm_animation.hpp"
#include "io/vrm_animation_pose.hpp"
#include "io/vrm_expressions.hpp"
#include "io/vrm_node_constraints.hpp"
#include "io/vrm_spring_pose.hpp"

namespace inkshade::io {

namespace {

constexpr size_t kMaxDepth = 1024;  // as read_gltf's node hierarchy

// Sets the weights `morphs` names in every mesh that has a target of that name (the last
// given wins). Throws for a name no mesh has.
void apply_named_weights(const tinygltf::Model& model, const std::vector<NamedWeight>& morphs,
                         std::vector<std::vector<float>>& weights, const std::string& path) {
    std::vector<std::string> all;  // every name, once, in file order: for the error
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const std::string& name : morph_target_names(mesh))
            if (!name.empty() && std::find(all.begin(), all.end(), name) == all.end()) all.push_back(name);
    for (const NamedWeight& m : morphs) {
        bool found = false;
        for (size_t n = 0; n < model.nodes.size(); ++n) {
            if (weights[n].empty()) continue;
            const int target = find_name(morph_target_names(model.meshes[size_t(model.nodes[n].mesh)]), m.name);
            if (target < 0) continue;
            weights[n][size_t(target)] = m.weight;
            found = true;
        }
        if (found) continue;
        if (all.empty())
            throw InputError(path, "no morph target '" + printable_name(m.name) +
                                       "': the file has no named morph targets (mesh.extras.targetNames)");
        throw InputError(path, unknown_name("morph target", m.name, all));
    }
}

}  // namespace

GltfPose::GltfPose(const tinygltf::Model& model, const std::string& path, const Pose& pose,
                   const GltfFloatReader& reader, FileTransform file_transform, std::vector<std::string>& warnings)
    : model_(model), path_(path), reader_(reader), file_transform_(file_transform) {
    const size_t n = model.nodes.size();
    parent_.assign(n, -1);
    for (size_t p = 0; p < n; ++p)
        for (int c : model.nodes[p].children)
            if (c >= 0 && size_t(c) < n && parent_[size_t(c)] < 0) parent_[size_t(c)] = int(p);
    world_.resize(n);

    // Morph weights: the mesh's, then the node's (section 3.7.2.2), then the animation's.
    weights_.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const tinygltf::Node& node = model.nodes[i];
        if (node.mesh < 0 || size_t(node.mesh) >= model.meshes.size()) continue;
        weights_[i] = default_morph_weights(model.meshes[size_t(node.mesh)]);
        for (size_t t = 0; t < weights_[i].size() && t < node.weights.size(); ++t)
            if (std::isfinite(node.weights[t])) weights_[i][t] = float(node.weights[t]);
    }
    const bool vrma = is_vrma_path(pose.animation);
    if (!pose.animation.empty() && !vrma) {
        const int index = find_gltf_animation(model, pose.animation, path);
        animated_ = sample_gltf_animation(model, index, double(pose.time), reader);
        for (size_t i = 0; i < n; ++i)
            if (animated_[i].weights)
                for (size_t t = 0; t < weights_[i].size() && t < animated_[i].weights->size(); ++t)
                    weights_[i][t] = (*animated_[i].weights)[t];
    }
    const std::vector<VrmExpression> expressions = read_vrm_expressions(model, path, warnings);
    std::optional<VrmAnimationPose> vrma_pose;
    if (vrma) vrma_pose.emplace(model, path, pose.animation, rest(), expressions, warnings);
    const std::vector<NamedWeight> expression_weights =
        vrma_pose ? vrma_pose->apply(double(pose.time), pose.expressions, *this, &warnings) : pose.expressions;
    if (!expressions.empty() || !expression_weights.empty())
        apply_vrm_expressions(expressions, expression_weights, weights_, path);
    apply_named_weights(model, pose.morphs, weights_, path);
    // three-vrm's VRM.update runs the node constraints after the humanoid, look-at and expressions.
    const std::vector<VrmNodeConstraint> constraints = read_vrm_node_constraints(model, path, warnings);
    const std::vector<size_t> order =
        constraints.empty() ? std::vector<size_t>{} : vrm_node_constraint_order(constraints, parent_, path);
    if (!constraints.empty()) apply_vrm_node_constraints(constraints, order, rest(), *this);
    // Spring bones after the node constraints, as VRM.update runs them; at each of their steps the
    // .vrma and the constraints pose the frame as they posed this one.
    VrmStepsAt vrm_steps;
    if (vrma_pose || !constraints.empty())
        vrm_steps = [&](double time, PoseNodes& nodes) {
            if (vrma_pose) vrma_pose->apply(time, {}, nodes, nullptr);
            if (!constraints.empty()) apply_vrm_node_constraints(constraints, order, rest(), nodes);
        };
    spring_ = pose_spring_bones(model, path, pose, reader, file_transform, parent_, vrm_steps, warnings);
    world_.assign(world_.size(), std::nullopt);  // the constraints' worlds predate the springs
}

const GltfRestPose& GltfPose::rest() const {
    if (!rest_) rest_ = gltf_rest_pose(parent_, [&](size_t i) { return file_transform_(model_.nodes[i], i, path_); });
    return *rest_;
}

glm::dquat GltfPose::rotation(size_t node) const {
    if (!animated_.empty() && animated_[node].rotation) return *animated_[node].rotation;
    return rest().rotation[node];
}

void GltfPose::set_rotation(size_t node, const glm::dquat& q) {
    animated_.resize(model_.nodes.size());
    animated_[node].rotation = q;
    world_.assign(world_.size(), std::nullopt);  // every world below the node changes
}

void GltfPose::set_translation(size_t node, const glm::dvec3& t) {
    animated_.resize(model_.nodes.size());
    animated_[node].translation = t;
    world_.assign(world_.size(), std::nullopt);
}

glm::dmat4 GltfPose::local(size_t index) const {
    const tinygltf::Node& node = model_.nodes[index];
    const glm::dmat4 file = file_transform_(node, index, path_);
    static const AnimatedNode still;
    const AnimatedNode& a = animated_.empty() ? still : animated_[index];
    const bool sprung = index < spring_.size() && spring_[index];
    if (!a.translation && !a.rotation && !a.scale && !sprung) return file;
    // The node's own T, R and S, each replaced where the animation sets it (section 3.11: an
    // animated node has no matrix; a file that gives one anyway has it decomposed, as three.js
    // does), the rotation by a spring bone's where a joint turns the node.
    NodeTrs n = file_node_trs(node, file);
    if (a.translation) n.t = *a.translation;
    if (a.rotation) n.r = *a.rotation;
    if (a.scale) n.s = *a.scale;
    if (sprung) n.r = *spring_[index];
    const double len = glm::length(n.r);
    return glm::translate(glm::dmat4(1.0), n.t) *
           glm::mat4_cast(len > 0.0 ? n.r / len : glm::dquat(1.0, 0.0, 0.0, 0.0)) * glm::scale(glm::dmat4(1.0), n.s);
}

glm::dmat4 GltfPose::world(size_t index) const {
    if (world_[index]) return *world_[index];
    std::vector<size_t> chain;  // index, its parent, ... up to a node whose world is known or a root
    for (int at = int(index); at >= 0 && !world_[size_t(at)]; at = parent_[size_t(at)]) {
        if (chain.size() > kMaxDepth)
            reader_.fail("node hierarchy above node " + std::to_string(index) + " is deeper than " +
                         std::to_string(kMaxDepth) + " or a cycle");
        chain.push_back(size_t(at));
    }
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        const int parent = parent_[*it];
        world_[*it] = (parent >= 0 ? *world_[size_t(parent)] : glm::dmat4(1.0)) * local(*it);
    }
    return *world_[index];
}

const std::vector<glm::dmat4>& GltfPose::joint_matrices(int skin) const {
    if (auto it = joint_matrices_.find(skin); it != joint_matrices_.end()) return it->second;
    const tinygltf::Skin& s = model_.skins[size_t(skin)];
    const std::string what = "skin " + std::to_string(skin);
    std::vector<float> inverse_bind;
    if (s.inverseBindMatrices >= 0) {
        int components = 0;
        inverse_bind = reader_.floats(s.inverseBindMatrices, "inverseBindMatrices of " + what, {16}, components);
        if (inverse_bind.size() / 16 < s.joints.size())
            reader_.fail("inverseBindMatrices of " + what + " has " + std::to_string(inverse_bind.size() / 16) +
                         " matrices for " + std::to_string(s.joints.size()) + " joints");
    }
    std::vector<glm::dmat4> matrices;
    for (size_t j = 0; j < s.joints.size(); ++j) {
        const int joint = s.joints[j];
        if (joint < 0 || size_t(joint) >= model_.nodes.size())
            reader_.fail(what + " joint " + std::to_string(j) + " is node " + std::to_string(joint) +
                         " but the file has " + std::to_string(model_.nodes.size()) + " nodes");
        glm::dmat4 ibm(1.0);  // section 3.7.3.1: identity when absent
        if (!inverse_bind.empty()) ibm = glm::dmat4(glm::make_mat4(inverse_bind.data() + 16 * j));  // column-major
        matrices.push_back(world(size_t(joint)) * ibm);
    }
    return joint_matrices_.emplace(skin, std::move(matrices)).first->second;
}

void GltfPose::deform(size_t node, const tinygltf::Primitive& primitive, std::vector<float>& positions,
                      std::vector<float>& normals, const std::string& where) const {
    if (!weights_[node].empty()) apply_morph_targets(primitive, weights_[node], positions, normals, where, reader_);
    const int skin = model_.nodes[node].skin;
    if (skin < 0) return;
    if (size_t(skin) >= model_.skins.size())
        reader_.fail("node " + std::to_string(node) + " refers to skin " + std::to_string(skin) + " but the file has " +
                     std::to_string(model_.skins.size()));
    auto attribute = [&](const char* name) {
        const auto it = primitive.attributes.find(name);
        if (it == primitive.attributes.end())
            reader_.fail(where + " is skinned (node " + std::to_string(node) + ", skin " + std::to_string(skin) +
                         ") but has no " + name);
        int components = 0;
        std::vector<float> values = reader_.floats(it->second, std::string(name) + " of " + where, {4}, components);
        if (values.size() != positions.size() / 3 * 4)
            reader_.fail(std::string(name) + " of " + where + " has " + std::to_string(values.size() / 4) +
                         " elements but POSITION has " + std::to_string(positions.size() / 3));
        return values;
    };
    const std::vector<float> joints = attribute("JOINTS_0");
    std::vector<float> weights = attribute("WEIGHTS_0");
    normalize_skin_weights(weights);
    skin_vertices(positions, normals, joints, weights, joint_matrices(skin), where, skin, reader_);
}

}  // namespace inkshade::io
