// VRM avatars with a full humanoid skeleton and VRM animations (.vrma) for the retargeting tests:
// bones with arbitrary rest rotations placed at T-pose world positions, a face mesh whose morph
// targets the expressions bind, a look-at, and VRMC_node_constraint nodes (roll, aim, rotation,
// one reading another); the .vrma has its own proportions and rest rotations, keys on a subset
// of the bones (one the avatars lack), hips translation, expressions and a look-at. No textures:
// three-vrm reads them in node as Inkshade does.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "io/gltf_files.hpp"

namespace inkshade::test {

// A bone: its name, parent (empty: under the root node), T-pose world position (facing +z,
// left at +x) and rest local rotation (axis, degrees).
struct RigBone {
    std::string name, parent;
    glm::dvec3 world;
    glm::dvec3 axis;
    double degrees;
};

// The avatar's skeleton (hips at y = 1).
inline std::vector<RigBone> avatar_rig_bones() {
    return {
        {"hips", "", {0, 1.0, 0}, {0, 1, 0}, 20},
        {"spine", "hips", {0, 1.1, 0.01}, {1, 0, 0}, -10},
        {"chest", "spine", {0, 1.25, 0}, {0, 0, 1}, 15},
        {"neck", "chest", {0, 1.45, -0.01}, {1, 1, 0}, 30},
        {"head", "neck", {0, 1.55, 0}, {0, 1, 1}, -25},
        {"leftEye", "head", {0.03, 1.62, 0.08}, {0, 1, 0}, 40},
        {"rightEye", "head", {-0.03, 1.62, 0.08}, {1, 0, 0}, -35},
        {"leftUpperLeg", "hips", {0.1, 0.95, 0}, {0, 0, 1}, 180},
        {"leftLowerLeg", "leftUpperLeg", {0.1, 0.5, 0.01}, {1, 0, 0}, 5},
        {"leftFoot", "leftLowerLeg", {0.1, 0.08, 0}, {0, 1, 0}, -60},
        {"rightUpperLeg", "hips", {-0.1, 0.95, 0}, {0, 0, 1}, 170},
        {"rightLowerLeg", "rightUpperLeg", {-0.1, 0.5, 0.01}, {1, 0, 1}, 12},
        {"rightFoot", "rightLowerLeg", {-0.1, 0.08, 0}, {0, 1, 0}, 45},
        {"leftShoulder", "chest", {0.05, 1.4, 0}, {0, 0, 1}, -80},
        {"leftUpperArm", "leftShoulder", {0.2, 1.4, 0}, {0, 0, 1}, -90},
        {"leftLowerArm", "leftUpperArm", {0.45, 1.4, -0.01}, {1, 0, 0}, 90},
        {"leftHand", "leftLowerArm", {0.7, 1.4, 0}, {0, 1, 0}, 10},
        {"rightShoulder", "chest", {-0.05, 1.4, 0}, {0, 0, 1}, 80},
        {"rightUpperArm", "rightShoulder", {-0.2, 1.4, 0}, {0, 0, 1}, 90},
        {"rightLowerArm", "rightUpperArm", {-0.45, 1.4, -0.01}, {0, 1, 0}, -20},
        {"rightHand", "rightLowerArm", {-0.7, 1.4, 0}, {1, 1, 1}, 30},
    };
}

// The .vrma's skeleton: other proportions (hips at 0.9) and rest rotations, an upperChest the
// avatars lack, no eyes, feet or shoulders.
inline std::vector<RigBone> animation_rig_bones() {
    return {
        {"hips", "", {0, 0.9, 0}, {0, 1, 0}, -90},
        {"spine", "hips", {0, 1.0, 0}, {0, 0, 1}, 20},
        {"chest", "spine", {0, 1.1, 0}, {1, 0, 0}, -15},
        {"upperChest", "chest", {0, 1.2, 0}, {0, 1, 0}, 35},
        {"neck", "upperChest", {0, 1.35, 0}, {1, 0, 1}, 10},
        {"head", "neck", {0, 1.45, 0}, {0, 0, 1}, -5},
        {"leftUpperLeg", "hips", {0.09, 0.85, 0}, {1, 0, 0}, 170},
        {"leftLowerLeg", "leftUpperLeg", {0.09, 0.45, 0}, {0, 1, 0}, 25},
        {"rightUpperLeg", "hips", {-0.09, 0.85, 0}, {0, 0, 1}, 160},
        {"rightLowerLeg", "rightUpperLeg", {-0.09, 0.45, 0}, {1, 1, 0}, -30},
        {"leftUpperArm", "upperChest", {0.18, 1.3, 0}, {0, 0, 1}, -70},
        {"leftLowerArm", "leftUpperArm", {0.4, 1.3, 0}, {0, 1, 0}, 45},
        {"leftHand", "leftLowerArm", {0.6, 1.3, 0}, {1, 0, 0}, -20},
        {"rightUpperArm", "upperChest", {-0.18, 1.3, 0}, {0, 0, 1}, 70},
        {"rightLowerArm", "rightUpperArm", {-0.4, 1.3, 0}, {0, 1, 1}, 15},
        {"rightHand", "rightLowerArm", {-0.6, 1.3, 0}, {1, 0, 0}, 5},
    };
}

inline nlohmann::json quaternion_json(const glm::dquat& q) { return {q.x, q.y, q.z, q.w}; }

inline glm::dquat axis_degrees(glm::dvec3 axis, double degrees) {
    return glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
}

// Adds the bones as nodes under `root` (world `root_world`, a rigid transform): each at its world
// position, `mirror` negating x and z (VRM 0.x avatars face -z). Returns bone -> node.
inline std::map<std::string, int> add_rig(GltfBuilder& g, const std::vector<RigBone>& bones, int root,
                                          const glm::dmat4& root_world, bool mirror = false) {
    std::map<std::string, int> nodes;
    std::map<std::string, glm::dmat4> world;
    const glm::dvec3 flip = mirror ? glm::dvec3(-1, 1, -1) : glm::dvec3(1);
    for (const RigBone& b : bones) {
        const int parent = b.parent.empty() ? root : nodes.at(b.parent);
        const glm::dmat4 parent_world = b.parent.empty() ? root_world : world.at(b.parent);
        const glm::dvec3 t = glm::dvec3(glm::inverse(parent_world) * glm::dvec4(b.world * flip, 1.0));
        const glm::dquat r = axis_degrees(b.axis, b.degrees);
        const int n =
            g.node({{"name", "J_" + b.name}, {"translation", {t.x, t.y, t.z}}, {"rotation", quaternion_json(r)}});
        g.doc["nodes"][size_t(parent)]["children"].push_back(n);
        nodes[b.name] = n;
        world[b.name] = parent_world * glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(r);
    }
    return nodes;
}

// A child node at `offset` from its parent (local), so that the parent's rotation shows in
// world positions.
inline int add_tip(GltfBuilder& g, int parent, const std::string& name, glm::dvec3 offset) {
    const int n = g.node({{"name", name}, {"translation", {offset.x, offset.y, offset.z}}});
    g.doc["nodes"][size_t(parent)]["children"].push_back(n);
    return n;
}

// The face: one triangle with a morph target per name (each moves one vertex).
inline int add_face(GltfBuilder& g, int head, const std::vector<std::string>& targets) {
    const int pos = g.floats({0, 0, 0.1f, 0.05f, 0, 0.1f, 0, 0.05f, 0.1f}, "VEC3", 3);
    nlohmann::json morphs = nlohmann::json::array();
    for (size_t i = 0; i < targets.size(); ++i) {
        std::vector<float> d(9, 0.0f);
        d[3 * (i % 3) + i % 2] = 0.01f * float(i + 1);
        morphs.push_back({{"POSITION", g.floats(d, "VEC3", 3)}});
    }
    const int mesh = g.mesh({{"POSITION", pos}});
    g.doc["meshes"][size_t(mesh)]["primitives"][0]["targets"] = morphs;
    g.doc["meshes"][size_t(mesh)]["extras"]["targetNames"] = targets;
    const int n = g.node({{"name", "Face"}, {"mesh", mesh}});
    g.doc["nodes"][size_t(head)]["children"].push_back(n);
    return n;
}

inline const std::vector<std::string> kRigMorphs = {"happy",    "blink",    "aa",        "lookUp",
                                                    "lookDown", "lookLeft", "lookRight", "wink"};

// A constraint node under `parent` (with a tip child), VRMC_node_constraint `kind` with `body`.
inline int add_constraint(GltfBuilder& g, int parent, const std::string& name, glm::dvec3 offset,
                          const glm::dquat& rest, const std::string& kind, nlohmann::json body) {
    const int n =
        g.node({{"name", name},
                {"translation", {offset.x, offset.y, offset.z}},
                {"rotation", quaternion_json(rest)},
                {"extensions", {{"VRMC_node_constraint", {{"specVersion", "1.0"}, {"constraint", {{kind, body}}}}}}}});
    g.doc["nodes"][size_t(parent)]["children"].push_back(n);
    add_tip(g, n, name + "Tip", {0.08, 0.03, 0.02});
    return n;
}

// Roll, aim and rotation constraints; the first reads the last (an order three-vrm resolves).
inline void add_constraints(GltfBuilder& g, const std::map<std::string, int>& bones) {
    const int hips = bones.at("hips"), chest = bones.at("chest");
    const int follower = add_constraint(g, hips, "RotationOfRoll", {0, -0.05, 0.1}, axis_degrees({0, 1, 0}, 15),
                                        "rotation", {{"source", -1}, {"weight", 0.7}});
    const int roll = add_constraint(g, bones.at("leftLowerArm"), "Roll", {0.1, 0, 0}, axis_degrees({1, 0, 0}, 20),
                                    "roll", {{"source", bones.at("leftHand")}, {"rollAxis", "X"}, {"weight", 0.5}});
    g.doc["nodes"][size_t(follower)]["extensions"]["VRMC_node_constraint"]["constraint"]["rotation"]["source"] = roll;
    add_constraint(g, chest, "Aim", {0, 0.05, 0.12}, axis_degrees({0, 0, 1}, -30), "aim",
                   {{"source", bones.at("rightHand")}, {"aimAxis", "NegativeY"}, {"weight", 0.8}});
    add_constraint(g, bones.at("rightUpperLeg"), "RollY", {0, -0.2, 0}, axis_degrees({1, 1, 0}, 25), "roll",
                   {{"source", bones.at("rightLowerLeg")}, {"rollAxis", "Y"}});
    add_constraint(g, hips, "Rotation", {0.05, 0, -0.1}, axis_degrees({0, 0, 1}, -10), "rotation",
                   {{"source", bones.at("spine")}, {"weight", 1.0}});
}

// The avatar: VRM 1.0 (bone look-at with range maps) or VRM 0.x (facing -z, BlendShape look-at),
// or with `other_look_at` the other type of look-at.
inline GltfBuilder rig_avatar(bool v0, bool other_look_at = false) {
    GltfBuilder g;
    const glm::dmat4 root_world = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 0.05));
    const int root = g.node({{"name", "Armature"}, {"translation", {0, 0, 0.05}}});
    const std::map<std::string, int> bones = add_rig(g, avatar_rig_bones(), root, root_world, v0);
    for (const char* eye : {"leftEye", "rightEye"}) add_tip(g, bones.at(eye), std::string(eye) + "Tip", {0, 0, 0.05});
    const int face = add_face(g, bones.at("head"), kRigMorphs);
    add_constraints(g, bones);
    g.scene({root});
    g.doc["extensionsUsed"] = {v0 ? "VRM" : "VRMC_vrm", "VRMC_node_constraint"};
    if (!v0) {
        nlohmann::json human = nlohmann::json::object(), preset = nlohmann::json::object();
        for (const auto& [bone, node] : bones) human[bone] = {{"node", node}};
        for (size_t i = 0; i + 1 < kRigMorphs.size(); ++i)
            preset[kRigMorphs[i]] = {{"morphTargetBinds", {{{"node", face}, {"index", i}, {"weight", 1.0}}}}};
        preset["happy"]["overrideMouth"] = "blend";
        preset["blink"]["isBinary"] = true;
        nlohmann::json custom = {{"wink", {{"morphTargetBinds", {{{"node", face}, {"index", 7}, {"weight", 0.5}}}}}}};
        g.doc["extensions"]["VRMC_vrm"] = {
            {"specVersion", "1.0"},
            {"meta", {{"name", "rig"}, {"authors", {"inkshade"}}, {"licenseUrl", "https://vrm.dev/licenses/1.0/"}}},
            {"humanoid", {{"humanBones", human}}},
            {"expressions", {{"preset", preset}, {"custom", custom}}},
            {"lookAt",
             {{"type", other_look_at ? "expression" : "bone"},
              {"offsetFromHeadBone", {0, 0.06, 0}},
              {"rangeMapHorizontalInner", {{"inputMaxValue", 60}, {"outputScale", 20}}},
              {"rangeMapHorizontalOuter", {{"inputMaxValue", 45}, {"outputScale", 30}}},
              {"rangeMapVerticalDown", {{"inputMaxValue", 50}, {"outputScale", 15}}},
              {"rangeMapVerticalUp", {{"inputMaxValue", 40}, {"outputScale", 25}}}}}};
        return g;
    }
    nlohmann::json human = nlohmann::json::array(), groups = nlohmann::json::array();
    for (const auto& [bone, node] : bones) human.push_back({{"bone", bone}, {"node", node}});
    const std::map<std::string, std::string> v0_names = {
        {"happy", "joy"},          {"blink", "blink"},       {"aa", "a"},
        {"lookUp", "lookup"},      {"lookDown", "lookdown"}, {"lookLeft", "lookleft"},
        {"lookRight", "lookright"}};
    const int mesh = g.doc["nodes"][size_t(face)]["mesh"];
    for (size_t i = 0; i < kRigMorphs.size(); ++i) {
        const auto preset = v0_names.find(kRigMorphs[i]);
        groups.push_back({{"name", kRigMorphs[i]},
                          {"presetName", preset == v0_names.end() ? "unknown" : preset->second},
                          {"binds", {{{"mesh", mesh}, {"index", i}, {"weight", 100}}}}});
    }
    auto degree_map = [](double x, double y) {
        return nlohmann::json{{"curve", {0, 0, 0, 1, 1, 1, 1, 0}}, {"xRange", x}, {"yRange", y}};
    };
    g.doc["extensions"]["VRM"] = {{"specVersion", "0.0"},
                                  {"meta", {{"title", "rig"}, {"author", "inkshade"}, {"version", "1"}}},
                                  {"humanoid", {{"humanBones", human}}},
                                  {"blendShapeMaster", {{"blendShapeGroups", groups}}},
                                  {"firstPerson",
                                   {{"firstPersonBone", bones.at("head")},
                                    {"firstPersonBoneOffset", {{"x", 0}, {"y", 0.06}, {"z", 0}}},
                                    {"lookAtTypeName", other_look_at ? "Bone" : "BlendShape"},
                                    {"lookAtHorizontalInner", degree_map(90, 1)},
                                    {"lookAtHorizontalOuter", degree_map(40, 0.8)},
                                    {"lookAtVerticalDown", degree_map(30, 0.9)},
                                    {"lookAtVerticalUp", degree_map(35, 0.7)}}}};
    return g;
}

// One keyframe track: a node's path with LINEAR, STEP or CUBICSPLINE values.
inline void add_track(GltfBuilder& g, nlohmann::json& animation, int node, const std::string& path,
                      const std::vector<float>& times, const std::vector<float>& values, const std::string& type,
                      const std::string& interpolation = "LINEAR") {
    const size_t components = type == "VEC4" ? 4 : 3;
    const int input = g.floats(times, "SCALAR", 1);
    const int output = g.floats(values, type, components);
    animation["samplers"].push_back({{"input", input}, {"output", output}, {"interpolation", interpolation}});
    animation["channels"].push_back(
        {{"sampler", animation["samplers"].size() - 1}, {"target", {{"node", node}, {"path", path}}}});
}

// The .vrma: a 2 s clip; rotations of most bones (the neck's STEP, which three-vrm-animation
// interpolates linearly), hips translation (CUBICSPLINE), expressions (one the avatars lack) and
// a look-at (STEP).
inline GltfBuilder rig_animation() {
    GltfBuilder g;
    const glm::dquat root_rotation = axis_degrees({0, 1, 0}, 90);
    const int root = g.node({{"name", "Root"}, {"rotation", quaternion_json(root_rotation)}});
    const std::map<std::string, int> bones = add_rig(g, animation_rig_bones(), root, glm::mat4_cast(root_rotation));
    nlohmann::json animation = {
        {"name", "clip"}, {"samplers", nlohmann::json::array()}, {"channels", nlohmann::json::array()}};
    const std::vector<float> times = {0.0f, 0.5f, 1.0f, 2.0f};
    const std::vector<double> angles = {0, 35, -20, 60};
    int k = 0;
    for (const RigBone& b : animation_rig_bones()) {
        ++k;
        const glm::dvec3 axis(std::sin(k * 1.3), std::cos(k * 0.7), std::sin(k * 2.1) + 0.2);
        std::vector<float> values;
        for (size_t i = 0; i < times.size(); ++i) {
            const glm::dquat q = axis_degrees(b.axis, b.degrees) * axis_degrees(axis, angles[i] * (0.5 + 0.1 * k));
            values.insert(values.end(), {float(q.x), float(q.y), float(q.z), float(q.w)});
        }
        add_track(g, animation, bones.at(b.name), "rotation", times, values, "VEC4",
                  b.name == "neck" ? "STEP" : "LINEAR");
    }
    // Hips translation in the root's (rotated) space.
    const glm::dvec3 rest = glm::dvec3(glm::inverse(glm::mat4_cast(root_rotation)) * glm::dvec4(0, 0.9, 0, 1));
    std::vector<float> hips;  // in-tangent, value, out-tangent per key
    for (size_t i = 0; i < times.size(); ++i) {
        for (int c = 0; c < 3; ++c) hips.push_back(float(0.2 * std::cos(double(i) * c)));
        for (int c = 0; c < 3; ++c) hips.push_back(float(rest[c] + 0.1 * std::sin(double(i) + c)));
        for (int c = 0; c < 3; ++c) hips.push_back(float(-0.3 * std::sin(double(i) + 2 * c)));
    }
    add_track(g, animation, bones.at("hips"), "translation", times, hips, "VEC3", "CUBICSPLINE");

    nlohmann::json preset = nlohmann::json::object(), custom = nlohmann::json::object();
    const std::vector<std::pair<std::string, std::vector<float>>> expressions = {{"happy", {0, 0.8f, 0.3f, 1}},
                                                                                 {"blink", {0, 0.4f, 0.9f, 0}},
                                                                                 {"aa", {1, 0.5f, 0, 0.2f}},
                                                                                 {"surprised", {0, 1, 1, 0}},
                                                                                 {"wink", {0.2f, 0.6f, 1, 0.5f}}};
    for (const auto& [name, weights] : expressions) {
        const int n = g.node({{"name", "Expression_" + name}});
        g.doc["nodes"][size_t(root)]["children"].push_back(n);
        (name == "wink" ? custom : preset)[name] = {{"node", n}};
        std::vector<float> values;
        for (float w : weights) values.insert(values.end(), {w, 0.0f, 0.0f});
        add_track(g, animation, n, "translation", times, values, "VEC3");
    }
    const int look = g.node({{"name", "LookAt"}});
    g.doc["nodes"][size_t(root)]["children"].push_back(look);
    std::vector<float> look_values;
    const std::vector<std::pair<double, double>> yaw_pitch = {{20, -10}, {-30, 15}, {50, 25}, {-10, -40}};
    for (const auto& [yaw, pitch] : yaw_pitch) {
        const glm::dquat q = axis_degrees({0, 1, 0}, yaw) * axis_degrees({1, 0, 0}, pitch);
        look_values.insert(look_values.end(), {float(q.x), float(q.y), float(q.z), float(q.w)});
    }
    add_track(g, animation, look, "rotation", times, look_values, "VEC4", "STEP");
    g.doc["animations"] = {animation};
    g.scene({root});

    nlohmann::json human = nlohmann::json::object();
    for (const auto& [bone, node] : bones) human[bone] = {{"node", node}};
    g.doc["extensionsUsed"] = {"VRMC_vrm_animation"};
    g.doc["extensions"]["VRMC_vrm_animation"] = {{"specVersion", "1.0"},
                                                 {"humanoid", {{"humanBones", human}}},
                                                 {"expressions", {{"preset", preset}, {"custom", custom}}},
                                                 {"lookAt", {{"node", look}}}};
    return g;
}

}  // namespace inkshade::test
