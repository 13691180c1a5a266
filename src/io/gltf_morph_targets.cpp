#include "io/gltf_morph_targets.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <cmath>

namespace inkshade::io {

size_t morph_target_count(const tinygltf::Mesh& mesh) {
    return mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
}

std::vector<std::string> morph_target_names(const tinygltf::Mesh& mesh) {
    std::vector<std::string> names(morph_target_count(mesh));
    if (!mesh.extras.IsObject() || !mesh.extras.Has("targetNames")) return names;
    const tinygltf::Value& list = mesh.extras.Get("targetNames");
    if (!list.IsArray()) return names;
    for (size_t i = 0; i < names.size() && i < list.ArrayLen(); ++i)
        if (list.Get(int(i)).IsString()) names[i] = list.Get(int(i)).Get<std::string>();
    return names;
}

std::vector<float> default_morph_weights(const tinygltf::Mesh& mesh) {
    std::vector<float> weights(morph_target_count(mesh), 0.0f);
    for (size_t i = 0; i < weights.size() && i < mesh.weights.size(); ++i)
        if (std::isfinite(mesh.weights[i])) weights[i] = float(mesh.weights[i]);
    return weights;
}

void apply_morph_targets(const tinygltf::Primitive& primitive, const std::vector<float>& weights,
                         std::vector<float>& positions, std::vector<float>& normals, const std::string& where,
                         const GltfFloatReader& reader) {
    for (size_t t = 0; t < primitive.targets.size() && t < weights.size(); ++t) {
        const double w = weights[t];
        if (w == 0.0) continue;
        for (const auto& [name, accessor] : primitive.targets[t]) {
            std::vector<float>* out = name == "POSITION" ? &positions : name == "NORMAL" ? &normals : nullptr;
            if (!out || out->empty()) continue;  // TANGENT, or normals the primitive does not have
            const std::string role = name + " of morph target " + std::to_string(t) + " of " + where;
            int components = 0;
            const std::vector<float> delta = reader.floats(accessor, role, {3}, components);
            if (delta.size() != out->size())
                reader.fail(role + " has " + std::to_string(delta.size() / 3) + " elements but POSITION has " +
                            std::to_string(positions.size() / 3));
            for (size_t i = 0; i < delta.size(); ++i) (*out)[i] = float(double((*out)[i]) + w * double(delta[i]));
        }
    }
}

}  // namespace inkshade::io
