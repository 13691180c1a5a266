#include "io/vrm_node_constraints.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "inkshade/error.hpp"
#include "io/unit_vector_rotation.hpp"
#include "io/gltf_value_member.hpp"

namespace inkshade::io {

namespace {

constexpr size_t kMaxChain = 1024;

std::string text_of(const tinygltf::Value& v) { return v.IsString() ? v.Get<std::string>() : ""; }

// three.js 0.187 Quaternion.slerp: a to b by t along the shorter arc; nearly parallel
// quaternions interpolate linearly, then normalise.
glm::dquat slerp(const glm::dquat& a, glm::dquat b, double t) {
    double cosine = glm::dot(a, b);
    if (cosine < 0.0) {
        b = -b;
        cosine = -cosine;
    }
    if (cosine >= 0.9995) return glm::normalize(a * (1.0 - t) + b * t);
    const double angle = std::acos(cosine), sine = std::sin(angle);
    return a * (std::sin((1.0 - t) * angle) / sine) + b * (std::sin(t * angle) / sine);
}

glm::dvec3 normalized_or_zero(const glm::dvec3& v) {
    const double len = glm::length(v);
    return len > 0.0 ? v / len : glm::dvec3(0.0);  // three.js Vector3.normalize
}

glm::dquat target_rotation(const VrmNodeConstraint& c, const GltfRestPose& rest, const PoseNodes& nodes) {
    const size_t dst = size_t(c.destination), src = size_t(c.source);
    const glm::dquat dst_rest = rest.rotation[dst], src_rest = rest.rotation[src];
    if (c.kind == VrmNodeConstraint::Kind::Rotation)  // VRMRotationConstraint.update
        return dst_rest * (glm::inverse(src_rest) * nodes.rotation(src));
    if (c.kind == VrmNodeConstraint::Kind::Roll) {  // VRMRollConstraint.update
        const glm::dquat delta = glm::inverse(dst_rest) * nodes.rotation(src) * glm::inverse(src_rest) * dst_rest;
        return dst_rest * from_unit_vectors(delta * c.axis, c.axis) * delta;
    }
    // VRMAimConstraint.update: the aim axis at rest, in world axes, to the source's direction.
    const int p = rest.parent[dst];
    const glm::dquat parent = p < 0 ? glm::dquat(1.0, 0.0, 0.0, 0.0) : rotation_of(nodes.world(size_t(p)));
    const glm::dvec3 from = parent * (dst_rest * c.axis);
    const glm::dvec3 to = normalized_or_zero(glm::dvec3(nodes.world(src)[3]) - glm::dvec3(nodes.world(dst)[3]));
    return glm::inverse(parent) * from_unit_vectors(from, to) * parent * dst_rest;
}

}  // namespace

std::vector<VrmNodeConstraint> read_vrm_node_constraints(const tinygltf::Model& model, const std::string& path,
                                                         std::vector<std::string>& warnings) {
    std::vector<VrmNodeConstraint> out;
    const auto& used = model.extensionsUsed;
    if (std::find(used.begin(), used.end(), "VRMC_node_constraint") == used.end()) return out;
    for (size_t n = 0; n < model.nodes.size(); ++n) {
        const auto ext = model.nodes[n].extensions.find("VRMC_node_constraint");
        if (ext == model.nodes[n].extensions.end()) continue;
        const std::string version = text_of(member(ext->second, "specVersion"));
        if (version != "1.0" && version != "1.0-beta") {
            warnings.push_back(path + ": node " + std::to_string(n) + "'s VRMC_node_constraint has specVersion '" +
                               version + "'; constraint ignored");
            continue;
        }
        const tinygltf::Value& def = member(ext->second, "constraint");
        VrmNodeConstraint c;
        c.destination = int(n);
        const tinygltf::Value* body = nullptr;
        if (const tinygltf::Value& roll = member(def, "roll"); roll.IsObject()) {
            c.kind = VrmNodeConstraint::Kind::Roll;
            const std::string axis = text_of(member(roll, "rollAxis"));
            c.axis = glm::dvec3(axis == "X" || axis.empty(), axis == "Y", axis == "Z");
            body = &roll;
        } else if (const tinygltf::Value& aim = member(def, "aim"); aim.IsObject()) {
            c.kind = VrmNodeConstraint::Kind::Aim;
            const std::string axis = text_of(member(aim, "aimAxis"));
            c.axis = glm::dvec3(axis == "PositiveX" || axis.empty() ? 1
                                : axis == "NegativeX"               ? -1
                                                                    : 0,
                                axis == "PositiveY"   ? 1
                                : axis == "NegativeY" ? -1
                                                      : 0,
                                axis == "PositiveZ"   ? 1
                                : axis == "NegativeZ" ? -1
                                                      : 0);
            body = &aim;
        } else if (const tinygltf::Value& rotation = member(def, "rotation"); rotation.IsObject()) {
            body = &rotation;
        } else {
            continue;
        }
        const tinygltf::Value& source = member(*body, "source");
        const double s = source.IsNumber() ? source.GetNumberAsDouble() : -1.0;
        if (!(s >= 0.0 && s < double(model.nodes.size()) && s == std::floor(s))) {
            warnings.push_back(path + ": node " + std::to_string(n) +
                               "'s VRMC_node_constraint has no valid source node; constraint ignored");
            continue;
        }
        c.source = int(s);
        const tinygltf::Value& weight = member(*body, "weight");
        if (weight.IsNumber() && std::isfinite(weight.GetNumberAsDouble())) c.weight = weight.GetNumberAsDouble();
        out.push_back(c);
    }
    return out;
}

std::vector<size_t> vrm_node_constraint_order(const std::vector<VrmNodeConstraint>& constraints,
                                              const std::vector<int>& parent, const std::string& path) {
    std::vector<std::vector<size_t>> on_node(parent.size());  // constraints by destination
    for (size_t i = 0; i < constraints.size(); ++i) on_node[size_t(constraints[i].destination)].push_back(i);
    std::vector<char> state(constraints.size(), 0);  // 1: tried, 2: done
    std::vector<size_t> order;
    // A node and its ancestors (a cycle in the parents ends the walk).
    auto with_ancestors = [&](int node) {
        std::vector<int> chain;
        for (int at = node; at >= 0 && chain.size() <= parent.size(); at = parent[size_t(at)]) chain.push_back(at);
        return chain;
    };
    std::function<void(size_t, size_t)> process = [&](size_t i, size_t depth) {
        if (state[i] == 2) return;
        if (depth > kMaxChain)  // a bound on the recursion, far above any avatar's
            throw InputError(path, "VRMC_node_constraint: constraints depend on each other more than " +
                                       std::to_string(kMaxChain) + " deep");
        if (state[i] == 1)
            throw InputError(path, "VRMC_node_constraint: circular dependency (the constraint on node " +
                                       std::to_string(constraints[i].destination) + " depends on itself)");
        state[i] = 1;
        const VrmNodeConstraint& c = constraints[i];
        std::vector<int> depends = {c.source};
        if (c.kind == VrmNodeConstraint::Kind::Aim && parent[size_t(c.destination)] >= 0)
            depends.push_back(parent[size_t(c.destination)]);
        for (int d : depends) {
            const std::vector<int> chain = with_ancestors(d);
            for (auto it = chain.rbegin(); it != chain.rend(); ++it)  // from the root, as three-vrm
                for (size_t j : on_node[size_t(*it)]) process(j, depth + 1);
        }
        state[i] = 2;
        order.push_back(i);
    };
    for (size_t i = 0; i < constraints.size(); ++i) process(i, 0);
    return order;
}

void apply_vrm_node_constraints(const std::vector<VrmNodeConstraint>& constraints, const std::vector<size_t>& order,
                                const GltfRestPose& rest, PoseNodes& nodes) {
    for (size_t i : order) {
        const VrmNodeConstraint& c = constraints[i];
        const glm::dquat dst_rest = rest.rotation[size_t(c.destination)];
        nodes.set_rotation(size_t(c.destination), slerp(dst_rest, target_rotation(c, rest, nodes), c.weight));
    }
}

}  // namespace inkshade::io
