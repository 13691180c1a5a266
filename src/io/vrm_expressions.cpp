#include "io/vrm_expressions.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "inkshade/error.hpp"
#include "io/gltf_morph_targets.hpp"
#include "io/gltf_names.hpp"
#include "io/gltf_value_member.hpp"

namespace inkshade::io {

namespace {

// The VRM 1.0 preset names (VRMC_vrm expressions.preset).
const std::vector<std::string> kPresets = {"happy",      "angry",  "sad",      "relaxed",  "surprised", "aa",
                                           "ih",         "ou",     "ee",       "oh",       "blink",     "blinkLeft",
                                           "blinkRight", "lookUp", "lookDown", "lookLeft", "lookRight", "neutral"};
// The expressions the override* properties damp (three-vrm's VRMExpressionManager).
const std::set<std::string> kBlink = {"blink", "blinkLeft", "blinkRight"};
const std::set<std::string> kLookAt = {"lookLeft", "lookRight", "lookUp", "lookDown"};
const std::set<std::string> kMouth = {"aa", "ee", "ih", "oh", "ou"};

// VRM 0.x presetName -> VRM 1.0 name (three-vrm's v0v1PresetNameMap); "unknown" has none.
const std::map<std::string, std::string> kV0Presets = {{"a", "aa"},
                                                       {"e", "ee"},
                                                       {"i", "ih"},
                                                       {"o", "oh"},
                                                       {"u", "ou"},
                                                       {"blink", "blink"},
                                                       {"joy", "happy"},
                                                       {"angry", "angry"},
                                                       {"sorrow", "sad"},
                                                       {"fun", "relaxed"},
                                                       {"lookup", "lookUp"},
                                                       {"lookdown", "lookDown"},
                                                       {"lookleft", "lookLeft"},
                                                       {"lookright", "lookRight"},
                                                       {"blink_l", "blinkLeft"},
                                                       {"blink_r", "blinkRight"},
                                                       {"neutral", "neutral"}};

double number_or(const tinygltf::Value& v, double fallback) {
    return v.IsNumber() && std::isfinite(v.GetNumberAsDouble()) ? v.GetNumberAsDouble() : fallback;
}

// An index member, or -1 when absent or not a non-negative integer below 2^31.
int index_of(const tinygltf::Value& v) {
    const double d = number_or(v, -1.0);
    return d >= 0.0 && d < 2147483647.0 && d == std::floor(d) ? int(d) : -1;
}

ExpressionOverride override_of(const tinygltf::Value& v) {
    if (!v.IsString()) return ExpressionOverride::None;
    const std::string& s = v.Get<std::string>();
    return s == "block"   ? ExpressionOverride::Block
           : s == "blend" ? ExpressionOverride::Blend
                          : ExpressionOverride::None;
}

class Reader {
public:
    Reader(const tinygltf::Model& model, const std::string& path, std::vector<std::string>& warnings)
        : model_(model), path_(path), warnings_(warnings) {}

    // A bind of `e` to morph target `target` of `node`'s mesh, or a warning.
    void bind(VrmExpression& e, int node, int target, double weight) {
        const std::string what = "expression '" + printable_name(e.name) + "'";
        if (node < 0 || size_t(node) >= model_.nodes.size()) {
            warnings_.push_back(path_ + ": " + what + " binds node " + std::to_string(node) +
                                ", which does not exist; bind left out");
            return;
        }
        const int mesh = model_.nodes[size_t(node)].mesh;
        const size_t targets =
            mesh >= 0 && size_t(mesh) < model_.meshes.size() ? morph_target_count(model_.meshes[size_t(mesh)]) : 0;
        if (target < 0 || size_t(target) >= targets) {
            warnings_.push_back(path_ + ": " + what + " binds morph target " + std::to_string(target) + " of node " +
                                std::to_string(node) + ", whose mesh has " + std::to_string(targets) +
                                "; bind left out");
            return;
        }
        e.binds.push_back({node, target, float(weight)});
    }

    // VRM 1.0: VRMC_vrm.expressions.preset and .custom, objects keyed by name.
    std::vector<VrmExpression> v1(const tinygltf::Value& expressions) {
        std::vector<VrmExpression> out;
        for (const char* group : {"preset", "custom"}) {
            const tinygltf::Value& list = member(expressions, group);
            if (!list.IsObject()) continue;
            const bool preset = group == std::string("preset");
            for (const std::string& name : list.Keys()) {
                const bool known = std::find(kPresets.begin(), kPresets.end(), name) != kPresets.end();
                if (preset != known) {  // three-vrm ignores both
                    warnings_.push_back(
                        path_ + ": " +
                        (preset ? "unknown preset expression '" : "custom expression named as a preset '") +
                        printable_name(name) + "' ignored");
                    continue;
                }
                const tinygltf::Value& x = list.Get(name);
                VrmExpression e;
                e.name = name;
                e.binary = member(x, "isBinary").IsBool() && member(x, "isBinary").Get<bool>();
                e.blink = override_of(member(x, "overrideBlink"));
                e.look_at = override_of(member(x, "overrideLookAt"));
                e.mouth = override_of(member(x, "overrideMouth"));
                const tinygltf::Value& binds = member(x, "morphTargetBinds");
                for (size_t i = 0; binds.IsArray() && i < binds.ArrayLen(); ++i) {
                    const tinygltf::Value& b = binds.Get(int(i));
                    bind(e, index_of(member(b, "node")), index_of(member(b, "index")),
                         number_or(member(b, "weight"), 1.0));
                }
                out.push_back(std::move(e));
            }
        }
        return out;
    }

    // VRM 0.x: blendShapeMaster.blendShapeGroups, binds by mesh (every node using the mesh).
    std::vector<VrmExpression> v0(const tinygltf::Value& groups) {
        std::vector<VrmExpression> out;
        for (size_t g = 0; g < groups.ArrayLen(); ++g) {
            const tinygltf::Value& x = groups.Get(int(g));
            const tinygltf::Value& preset = member(x, "presetName");
            const auto v1_name = preset.IsString() ? kV0Presets.find(preset.Get<std::string>()) : kV0Presets.end();
            VrmExpression e;
            if (v1_name != kV0Presets.end())
                e.name = v1_name->second;
            else if (member(x, "name").IsString())
                e.name = member(x, "name").Get<std::string>();
            if (e.name.empty()) {
                warnings_.push_back(path_ + ": blend shape group " + std::to_string(g) + " has no name; ignored");
                continue;
            }
            if (std::any_of(out.begin(), out.end(), [&](const VrmExpression& o) { return o.name == e.name; })) {
                warnings_.push_back(path_ + ": expression '" + printable_name(e.name) +
                                    "' is given twice; the later one ignored");
                continue;
            }
            e.binary = member(x, "isBinary").IsBool() && member(x, "isBinary").Get<bool>();
            const tinygltf::Value& binds = member(x, "binds");
            for (size_t i = 0; binds.IsArray() && i < binds.ArrayLen(); ++i) {
                const tinygltf::Value& b = binds.Get(int(i));
                const int mesh = index_of(member(b, "mesh")), target = index_of(member(b, "index"));
                const double weight = 0.01 * number_or(member(b, "weight"), 100.0);  // 0..100 -> 0..1
                for (size_t n = 0; n < model_.nodes.size(); ++n)
                    if (mesh >= 0 && model_.nodes[n].mesh == mesh) bind(e, int(n), target, weight);
            }
            out.push_back(std::move(e));
        }
        return out;
    }

private:
    const tinygltf::Model& model_;
    const std::string& path_;
    std::vector<std::string>& warnings_;
};

// How much an expression at `weight` damps the expressions its override names.
double override_amount(ExpressionOverride o, double weight) {
    return o == ExpressionOverride::Block ? (weight > 0.0 ? 1.0 : 0.0) : o == ExpressionOverride::Blend ? weight : 0.0;
}

}  // namespace

bool is_vrm_preset(const std::string& name) {
    return std::find(kPresets.begin(), kPresets.end(), name) != kPresets.end();
}

std::vector<VrmExpression> read_vrm_expressions(const tinygltf::Model& model, const std::string& path,
                                                std::vector<std::string>& warnings) {
    Reader reader(model, path, warnings);
    if (auto v1 = model.extensions.find("VRMC_vrm"); v1 != model.extensions.end()) {
        const tinygltf::Value& expressions = member(v1->second, "expressions");
        if (expressions.IsObject()) return reader.v1(expressions);
    }
    if (auto v0 = model.extensions.find("VRM"); v0 != model.extensions.end()) {
        const tinygltf::Value& groups = member(member(v0->second, "blendShapeMaster"), "blendShapeGroups");
        if (groups.IsArray()) return reader.v0(groups);
    }
    return {};
}

void apply_vrm_expressions(const std::vector<VrmExpression>& expressions, const std::vector<NamedWeight>& weights,
                           std::vector<std::vector<float>>& node_weights, const std::string& path) {
    std::vector<std::string> names;
    for (const VrmExpression& e : expressions) names.push_back(e.name);
    std::vector<double> weight(expressions.size(), 0.0);
    for (const NamedWeight& w : weights) {
        const int i = find_name(names, w.name);
        if (i < 0) {
            if (names.empty())
                throw InputError(path,
                                 "no expression '" + printable_name(w.name) + "': the file has no VRM expressions");
            throw InputError(path, unknown_name("expression", w.name, names));
        }
        weight[size_t(i)] = std::clamp(double(w.weight), 0.0, 1.0);  // three-vrm's setValue saturates
    }
    double blink = 1.0, look_at = 1.0, mouth = 1.0;
    for (size_t i = 0; i < expressions.size(); ++i) {
        blink -= override_amount(expressions[i].blink, weight[i]);
        look_at -= override_amount(expressions[i].look_at, weight[i]);
        mouth -= override_amount(expressions[i].mouth, weight[i]);
    }
    for (const VrmExpression& e : expressions)
        for (const VrmExpression::Bind& b : e.binds) node_weights[size_t(b.node)][size_t(b.target)] = 0.0f;
    for (size_t i = 0; i < expressions.size(); ++i) {
        const VrmExpression& e = expressions[i];
        double w = e.binary ? (weight[i] <= 0.5 ? 0.0 : 1.0) : weight[i];
        if (kBlink.count(e.name)) w *= std::max(blink, 0.0);
        if (kLookAt.count(e.name)) w *= std::max(look_at, 0.0);
        if (kMouth.count(e.name)) w *= std::max(mouth, 0.0);
        for (const VrmExpression::Bind& b : e.binds)
            node_weights[size_t(b.node)][size_t(b.target)] += float(b.weight * w);
    }
}

}  // namespace inkshade::io
