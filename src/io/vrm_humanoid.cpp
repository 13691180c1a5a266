#include "io/vrm_humanoid.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

#include <cmath>

#include "inkshade/error.hpp"
#include "io/gltf_names.hpp"
#include "io/gltf_value_member.hpp"

namespace inkshade::io {

namespace {

// A node index member, or -1 when absent or not a non-negative integer.
int index_of(const tinygltf::Value& v) {
    if (!v.IsNumber()) return -1;
    const double d = v.GetNumberAsDouble();
    return d >= 0.0 && d < 2147483647.0 && d == std::floor(d) ? int(d) : -1;
}

// three-vrm's thumbBoneNameMap: VRM 0.x (and 1.0-beta) thumb names -> VRM 1.0's.
std::string renamed_thumb(const std::string& bone) {
    static const std::map<std::string, std::string> names = {{"leftThumbProximal", "leftThumbMetacarpal"},
                                                             {"leftThumbIntermediate", "leftThumbProximal"},
                                                             {"rightThumbProximal", "rightThumbMetacarpal"},
                                                             {"rightThumbIntermediate", "rightThumbProximal"}};
    const auto it = names.find(bone);
    return it == names.end() ? bone : it->second;
}

// three-vrm's VRMRequiredHumanBoneName.
const char* const kRequired[] = {"hips",         "spine",         "head",          "leftUpperLeg",  "leftLowerLeg",
                                 "leftFoot",     "rightUpperLeg", "rightLowerLeg", "rightFoot",     "leftUpperArm",
                                 "leftLowerArm", "leftHand",      "rightUpperArm", "rightLowerArm", "rightHand"};

}  // namespace

const std::vector<std::pair<std::string, std::string>>& vrm_human_bones() {
    static const std::vector<std::pair<std::string, std::string>> bones = {
        {"hips", ""},
        {"spine", "hips"},
        {"chest", "spine"},
        {"upperChest", "chest"},
        {"neck", "upperChest"},
        {"head", "neck"},
        {"leftEye", "head"},
        {"rightEye", "head"},
        {"jaw", "head"},
        {"leftUpperLeg", "hips"},
        {"leftLowerLeg", "leftUpperLeg"},
        {"leftFoot", "leftLowerLeg"},
        {"leftToes", "leftFoot"},
        {"rightUpperLeg", "hips"},
        {"rightLowerLeg", "rightUpperLeg"},
        {"rightFoot", "rightLowerLeg"},
        {"rightToes", "rightFoot"},
        {"leftShoulder", "upperChest"},
        {"leftUpperArm", "leftShoulder"},
        {"leftLowerArm", "leftUpperArm"},
        {"leftHand", "leftLowerArm"},
        {"rightShoulder", "upperChest"},
        {"rightUpperArm", "rightShoulder"},
        {"rightLowerArm", "rightUpperArm"},
        {"rightHand", "rightLowerArm"},
        {"leftThumbMetacarpal", "leftHand"},
        {"leftThumbProximal", "leftThumbMetacarpal"},
        {"leftThumbDistal", "leftThumbProximal"},
        {"leftIndexProximal", "leftHand"},
        {"leftIndexIntermediate", "leftIndexProximal"},
        {"leftIndexDistal", "leftIndexIntermediate"},
        {"leftMiddleProximal", "leftHand"},
        {"leftMiddleIntermediate", "leftMiddleProximal"},
        {"leftMiddleDistal", "leftMiddleIntermediate"},
        {"leftRingProximal", "leftHand"},
        {"leftRingIntermediate", "leftRingProximal"},
        {"leftRingDistal", "leftRingIntermediate"},
        {"leftLittleProximal", "leftHand"},
        {"leftLittleIntermediate", "leftLittleProximal"},
        {"leftLittleDistal", "leftLittleIntermediate"},
        {"rightThumbMetacarpal", "rightHand"},
        {"rightThumbProximal", "rightThumbMetacarpal"},
        {"rightThumbDistal", "rightThumbProximal"},
        {"rightIndexProximal", "rightHand"},
        {"rightIndexIntermediate", "rightIndexProximal"},
        {"rightIndexDistal", "rightIndexIntermediate"},
        {"rightMiddleProximal", "rightHand"},
        {"rightMiddleIntermediate", "rightMiddleProximal"},
        {"rightMiddleDistal", "rightMiddleIntermediate"},
        {"rightRingProximal", "rightHand"},
        {"rightRingIntermediate", "rightRingProximal"},
        {"rightRingDistal", "rightRingIntermediate"},
        {"rightLittleProximal", "rightHand"},
        {"rightLittleIntermediate", "rightLittleProximal"},
        {"rightLittleDistal", "rightLittleIntermediate"},
    };
    return bones;
}

std::optional<VrmHumanoid> read_vrm_humanoid(const tinygltf::Model& model, const std::string& path,
                                             std::vector<std::string>& warnings) {
    VrmHumanoid humanoid;
    auto add = [&](std::string bone, int node) {
        if (node < 0 || size_t(node) >= model.nodes.size()) {
            warnings.push_back(path + ": humanoid bone '" + printable_name(bone) + "' is node " + std::to_string(node) +
                               ", which does not exist; bone left out");
            return;
        }
        if (!humanoid.bones.emplace(std::move(bone), node).second)
            warnings.push_back(path + ": humanoid bone given twice; the later one ignored");
    };
    if (auto v1 = model.extensions.find("VRMC_vrm"); v1 != model.extensions.end()) {
        const tinygltf::Value& bones = member(member(v1->second, "humanoid"), "humanBones");
        if (!bones.IsObject()) return std::nullopt;
        // three-vrm renames the thumbs only when the file uses the old names.
        const bool old_thumbs = bones.Has("leftThumbIntermediate") || bones.Has("rightThumbIntermediate");
        for (const std::string& name : bones.Keys())
            add(old_thumbs ? renamed_thumb(name) : name, index_of(member(bones.Get(name), "node")));
    } else if (auto v0 = model.extensions.find("VRM"); v0 != model.extensions.end()) {
        const tinygltf::Value& bones = member(member(v0->second, "humanoid"), "humanBones");
        if (!bones.IsArray()) return std::nullopt;
        humanoid.v0 = true;
        for (size_t i = 0; i < bones.ArrayLen(); ++i) {
            const tinygltf::Value& b = bones.Get(int(i));
            if (member(b, "bone").IsString() && member(b, "node").IsNumber())
                add(renamed_thumb(member(b, "bone").Get<std::string>()), index_of(member(b, "node")));
        }
    } else {
        return std::nullopt;
    }
    std::string missing;
    for (const char* bone : kRequired)
        if (!humanoid.bones.count(bone)) missing += (missing.empty() ? "" : ", ") + std::string(bone);
    if (!missing.empty()) throw InputError(path, "the VRM humanoid lacks required bones: " + missing);
    return humanoid;
}

glm::dquat raw_bone_rotation(const VrmHumanoid& humanoid, const GltfRestPose& rest, const std::string& bone,
                             const glm::dquat& normalized) {
    const size_t node = size_t(humanoid.node(bone));
    return raw_bone_rotation(rest.parent_world_rotation(node), rest.rotation[node], normalized);
}

}  // namespace inkshade::io
