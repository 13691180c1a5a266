// A small procedural avatar for the posing tests, written as VRM 1.0, VRM 0.x or plain glTF:
// a capsule body, a head with two named morph targets ("happy", "blink") bound by VRM
// expressions, and a two-joint arm (shoulder and elbow joints under a hips joint) skinned with
// linear blend weights, with a red unlit ball at the hand. Everything is built from spheres and
// tubes, so each vertex's posed place has a closed form the tests compute (avatar_* functions).
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "io/gltf_files.hpp"

namespace inkshade::test {

// Where the skeleton stands in the bind pose (world space, metres, +y up, facing +z).
constexpr float kHipsY = 1.0f;
inline const glm::vec3 kShoulder{0.2f, 1.3f, 0.0f};   // UpperArm joint
inline const glm::vec3 kElbow{0.5f, 1.3f, 0.0f};      // LowerArm joint
inline const glm::vec3 kHandBall{0.86f, 1.3f, 0.0f};  // centre of the red ball at the hand
constexpr float kHandBallRadius = 0.05f;
inline const glm::vec3 kHeadCentre{0.0f, 1.62f, 0.0f};
constexpr float kHeadRadius = 0.2f;
// The file's own pose of the elbow (LowerArm's rotation about +z) and the "wave" animation's
// shoulder angle (UpperArm about +z): 0 at t = 0 to 90 degrees at t = 2 s, linear.
constexpr float kFileElbowDegrees = 30.0f;
constexpr float kWaveEndDegrees = 90.0f, kWaveEndSeconds = 2.0f;

struct AvatarPart {
    std::vector<float> positions, normals;  // xyz triples, bind pose (the head's about its node)
    std::vector<uint16_t> indices;
};

// Triangles facing away from `inside(centroid)`; degenerate ones (a sphere's poles) dropped.
template <class Inside>
void orient_outwards(AvatarPart& part, Inside inside) {
    std::vector<uint16_t> kept;
    auto at = [&](uint16_t i) {
        return glm::vec3(part.positions[3 * i], part.positions[3 * i + 1], part.positions[3 * i + 2]);
    };
    for (size_t t = 0; t + 2 < part.indices.size(); t += 3) {
        uint16_t a = part.indices[t], b = part.indices[t + 1], c = part.indices[t + 2];
        const glm::vec3 n = glm::cross(at(b) - at(a), at(c) - at(a));
        if (glm::length(n) < 1e-9f) continue;
        const glm::vec3 centroid = (at(a) + at(b) + at(c)) / 3.0f;
        if (glm::dot(n, centroid - inside(centroid)) < 0.0f) std::swap(b, c);
        kept.insert(kept.end(), {a, b, c});
    }
    part.indices = kept;
}

// A latitude-longitude sphere.
inline AvatarPart avatar_sphere(glm::vec3 centre, float radius, int rings, int segments) {
    AvatarPart s;
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j <= segments; ++j) {
            const float theta = float(M_PI) * float(i) / float(rings),
                        phi = 2.0f * float(M_PI) * float(j) / float(segments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            const glm::vec3 p = centre + radius * n;
            s.positions.insert(s.positions.end(), {p.x, p.y, p.z});
            s.normals.insert(s.normals.end(), {n.x, n.y, n.z});
        }
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const uint16_t a = uint16_t(i * (segments + 1) + j), b = uint16_t(a + segments + 1);
            s.indices.insert(s.indices.end(), {a, b, uint16_t(a + 1), uint16_t(a + 1), b, uint16_t(b + 1)});
        }
    orient_outwards(s, [&](glm::vec3) { return centre; });
    return s;
}

// A capsule along +y: a tube between two half spheres (a sphere split at its equator).
inline AvatarPart avatar_capsule(glm::vec3 bottom, float height, float radius) {
    const int rings = 8, segments = 16;
    AvatarPart s;
    for (int i = 0; i <= rings + 1; ++i)
        for (int j = 0; j <= segments; ++j) {
            const int k = i <= rings / 2 ? i : i - 1;  // the equator ring twice, once per half
            const float theta = float(M_PI) * float(k) / float(rings),
                        phi = 2.0f * float(M_PI) * float(j) / float(segments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            const glm::vec3 p = bottom + glm::vec3(0, radius + (i <= rings / 2 ? height : 0.0f), 0) + radius * n;
            s.positions.insert(s.positions.end(), {p.x, p.y, p.z});
            s.normals.insert(s.normals.end(), {n.x, n.y, n.z});
        }
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const uint16_t a = uint16_t(i * (segments + 1) + j), b = uint16_t(a + segments + 1);
            s.indices.insert(s.indices.end(), {a, b, uint16_t(a + 1), uint16_t(a + 1), b, uint16_t(b + 1)});
        }
    const float y0 = bottom.y + radius, y1 = y0 + height;
    orient_outwards(s, [&](glm::vec3 c) { return glm::vec3(bottom.x, std::clamp(c.y, y0, y1), bottom.z); });
    return s;
}

// The arm: an octagonal tube along +x from the shoulder to x = 0.8 with rings every 0.15 m
// (the middle one at the elbow), closed by flat caps.
constexpr float kArmEnd = 0.8f, kArmRadius = 0.05f;
inline AvatarPart avatar_arm() {
    AvatarPart s;
    const int sides = 8;
    const std::vector<float> xs = {kShoulder.x, 0.35f, kElbow.x, 0.65f, kArmEnd};
    for (float x : xs)
        for (int j = 0; j < sides; ++j) {
            const float a = 2.0f * float(M_PI) * float(j) / float(sides);
            const glm::vec3 n(0, std::cos(a), std::sin(a));
            const glm::vec3 p = glm::vec3(x, kShoulder.y, kShoulder.z) + kArmRadius * n;
            s.positions.insert(s.positions.end(), {p.x, p.y, p.z});
            s.normals.insert(s.normals.end(), {n.x, n.y, n.z});
        }
    for (size_t r = 0; r + 1 < xs.size(); ++r)
        for (int j = 0; j < sides; ++j) {
            const uint16_t a = uint16_t(r * sides + size_t(j)), b = uint16_t(r * sides + size_t((j + 1) % sides));
            s.indices.insert(s.indices.end(), {a, b, uint16_t(a + sides), uint16_t(a + sides), b, uint16_t(b + sides)});
        }
    orient_outwards(s, [&](glm::vec3 c) { return glm::vec3(c.x, kShoulder.y, kShoulder.z); });
    for (float x : {xs.front(), xs.back()}) {  // caps: their own vertices, with axial normals
        const float nx = x == xs.front() ? -1.0f : 1.0f;
        AvatarPart cap;
        cap.positions = {x, kShoulder.y, kShoulder.z};
        cap.normals = {nx, 0, 0};
        for (int j = 0; j < sides; ++j) {
            const float a = 2.0f * float(M_PI) * float(j) / float(sides);
            cap.positions.insert(cap.positions.end(),
                                 {x, kShoulder.y + kArmRadius * std::cos(a), kShoulder.z + kArmRadius * std::sin(a)});
            cap.normals.insert(cap.normals.end(), {nx, 0, 0});
            cap.indices.insert(cap.indices.end(), {0, uint16_t(1 + j), uint16_t(1 + (j + 1) % sides)});
        }
        orient_outwards(cap, [&](glm::vec3 c) { return c - glm::vec3(nx, 0, 0); });
        const uint16_t base = uint16_t(s.positions.size() / 3);
        for (uint16_t i : cap.indices) s.indices.push_back(uint16_t(base + i));
        s.positions.insert(s.positions.end(), cap.positions.begin(), cap.positions.end());
        s.normals.insert(s.normals.end(), cap.normals.begin(), cap.normals.end());
    }
    return s;
}

// Skin weights of an arm vertex (joint 0 UpperArm, joint 1 LowerArm): the upper arm's rings
// follow the shoulder, the elbow ring both joints half and half, the forearm the elbow.
inline glm::vec2 avatar_arm_weights(float x) {
    if (x < kElbow.x - 0.01f) return {1, 0};
    if (x > kElbow.x + 0.01f) return {0, 1};
    return {0.5f, 0.5f};
}

// The head's morph targets, as displacements of its vertices (head-local positions): "happy"
// lifts the lower front (a smile), "blink" lowers the upper front.
inline glm::vec3 avatar_happy(glm::vec3 p) {
    return p.z > 0.0f && p.y < 0.0f ? glm::vec3(0, 0.2f * p.z, 0.05f * p.z) : glm::vec3(0);
}
inline glm::vec3 avatar_blink(glm::vec3 p) {
    return p.z > 0.0f && p.y > 0.0f ? glm::vec3(0, -0.15f * p.z, 0) : glm::vec3(0);
}

// The joints' world matrices for a shoulder angle (the elbow keeps the file's angle).
inline glm::mat4 avatar_upper_arm(float shoulder_degrees) {
    return glm::translate(glm::mat4(1), kShoulder) *
           glm::mat4_cast(glm::angleAxis(glm::radians(shoulder_degrees), glm::vec3(0, 0, 1)));
}
inline glm::mat4 avatar_lower_arm(float shoulder_degrees) {
    return avatar_upper_arm(shoulder_degrees) * glm::translate(glm::mat4(1), kElbow - kShoulder) *
           glm::mat4_cast(glm::angleAxis(glm::radians(kFileElbowDegrees), glm::vec3(0, 0, 1)));
}
// Linear blend skinning of a bind-pose point by the analytic joints: sum_k w_k J_k B_k^-1 p.
inline glm::vec3 avatar_skinned(glm::vec3 p, glm::vec2 w, float shoulder_degrees) {
    const glm::vec4 upper = avatar_upper_arm(shoulder_degrees) * glm::vec4(p - kShoulder, 1.0f);
    const glm::vec4 lower = avatar_lower_arm(shoulder_degrees) * glm::vec4(p - kElbow, 1.0f);
    return glm::vec3(w.x * upper + w.y * lower);
}

inline nlohmann::json avatar_quaternion(float degrees) {  // about +z
    const float h = 0.5f * glm::radians(degrees);
    return {0, 0, std::sin(h), std::cos(h)};
}

enum class AvatarFormat { Vrm1, Vrm0, Gltf };

// The avatar; node order: Avatar (root), Body, Head, Arm (skinned), Hips > UpperArm > LowerArm.
// Mesh vertices in load order: body, head, arm, hand ball. Animations: "wave" (the shoulder and,
// as weights, "happy": 0 -> 1 over the same time) and "hop" (the root's translation, STEP).
inline GltfBuilder avatar(AvatarFormat format) {
    using nlohmann::json;
    GltfBuilder g;
    auto part_mesh = [&](const AvatarPart& part, int material, json extra = json::object()) {
        json attributes = {{"POSITION", g.floats(part.positions, "VEC3", 3)},
                           {"NORMAL", g.floats(part.normals, "VEC3", 3)}};
        attributes.update(extra);
        json p = {{"attributes", attributes},
                  {"indices", g.data(part.indices, kUShort, 1, "SCALAR")},
                  {"material", material}};
        return p;
    };
    const int skin_material = g.material({0.95f, 0.8f, 0.7f, 1.0f});
    const int cloth_material = g.material({0.3f, 0.45f, 0.8f, 1.0f});
    const int ball_material = g.material({1.0f, 0.0f, 0.0f, 1.0f});
    g.doc["materials"][ball_material]["extensions"]["KHR_materials_unlit"] = json::object();
    g.doc["extensionsUsed"] = {"KHR_materials_unlit"};

    // Body.
    const AvatarPart body = avatar_capsule({0, 0.35f, 0}, 0.75f, 0.2f);
    g.doc["meshes"].push_back({{"name", "Body"}, {"primitives", {part_mesh(body, cloth_material)}}});
    const int body_mesh = int(g.doc["meshes"].size()) - 1;

    // Head with two morph targets, named in extras.targetNames.
    const AvatarPart head = avatar_sphere(glm::vec3(0), kHeadRadius, 12, 16);
    std::vector<float> happy, blink, none(head.positions.size(), 0.0f);
    for (size_t i = 0; i < head.positions.size(); i += 3) {
        const glm::vec3 p(head.positions[i], head.positions[i + 1], head.positions[i + 2]);
        const glm::vec3 h = avatar_happy(p), b = avatar_blink(p);
        happy.insert(happy.end(), {h.x, h.y, h.z});
        blink.insert(blink.end(), {b.x, b.y, b.z});
    }
    json head_primitive = part_mesh(head, skin_material);
    head_primitive["targets"] = {{{"POSITION", g.floats(happy, "VEC3", 3)}},
                                 {{"POSITION", g.floats(blink, "VEC3", 3)}, {"NORMAL", g.floats(none, "VEC3", 3)}}};
    g.doc["meshes"].push_back({{"name", "Head"},
                               {"primitives", {head_primitive}},
                               {"weights", {0.0, 0.0}},
                               {"extras", {{"targetNames", {"happy", "blink"}}}}});
    const int head_mesh = int(g.doc["meshes"].size()) - 1;

    // The arm and the hand ball, skinned to UpperArm (joint 0) and LowerArm (joint 1).
    const AvatarPart arm = avatar_arm();
    std::vector<uint8_t> arm_joints;
    std::vector<float> arm_weights;
    for (size_t i = 0; i < arm.positions.size(); i += 3) {
        const glm::vec2 w = avatar_arm_weights(arm.positions[i]);
        arm_joints.insert(arm_joints.end(), {0, 1, 0, 0});
        arm_weights.insert(arm_weights.end(), {w.x, w.y, 0, 0});
    }
    const AvatarPart ball = avatar_sphere(kHandBall, kHandBallRadius, 8, 12);
    std::vector<uint8_t> ball_joints;
    std::vector<float> ball_weights;
    for (size_t i = 0; i < ball.positions.size(); i += 3) {
        ball_joints.insert(ball_joints.end(), {1, 0, 0, 0});
        ball_weights.insert(ball_weights.end(), {1, 0, 0, 0});
    }
    json arm_primitives = {part_mesh(arm, skin_material,
                                     {{"JOINTS_0", g.data(arm_joints, kUByte, 4, "VEC4")},
                                      {"WEIGHTS_0", g.floats(arm_weights, "VEC4", 4)}}),
                           part_mesh(ball, ball_material,
                                     {{"JOINTS_0", g.data(ball_joints, kUByte, 4, "VEC4")},
                                      {"WEIGHTS_0", g.floats(ball_weights, "VEC4", 4)}})};
    g.doc["meshes"].push_back({{"name", "Arm"}, {"primitives", arm_primitives}});
    const int arm_mesh = int(g.doc["meshes"].size()) - 1;

    // Nodes: 0 Avatar, 1 Body, 2 Head, 3 Arm, 4 Hips, 5 UpperArm, 6 LowerArm.
    g.node({{"name", "Avatar"}, {"children", {1, 2, 3, 4}}});
    g.node({{"name", "Body"}, {"mesh", body_mesh}});
    g.node({{"name", "Head"}, {"mesh", head_mesh}, {"translation", {kHeadCentre.x, kHeadCentre.y, kHeadCentre.z}}});
    g.node({{"name", "Arm"}, {"mesh", arm_mesh}, {"skin", 0}});
    g.node({{"name", "Hips"}, {"translation", {0, kHipsY, 0}}, {"children", {5}}});
    g.node(
        {{"name", "UpperArm"}, {"translation", {kShoulder.x, kShoulder.y - kHipsY, kShoulder.z}}, {"children", {6}}});
    g.node({{"name", "LowerArm"},
            {"translation", {kElbow.x - kShoulder.x, 0, 0}},
            {"rotation", avatar_quaternion(kFileElbowDegrees)}});
    g.scene({0});
    // Inverse bind matrices: the joints' bind-pose worlds are translations.
    const std::vector<float> ibm = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -kShoulder.x, -kShoulder.y, -kShoulder.z, 1,
                                    1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -kElbow.x,    -kElbow.y,    -kElbow.z,    1};
    g.doc["skins"] = {
        {{"name", "ArmSkin"}, {"joints", {5, 6}}, {"skeleton", 4}, {"inverseBindMatrices", g.floats(ibm, "MAT4", 16)}}};

    // Animations: "wave" turns the shoulder and smiles; "hop" lifts the whole avatar in steps.
    const int wave_times = g.floats({0.0f, kWaveEndSeconds}, "SCALAR", 1);
    std::vector<float> rotations;
    for (float d : {0.0f, kWaveEndDegrees})
        for (const auto& c : avatar_quaternion(d)) rotations.push_back(c.get<float>());
    const int wave_rotations = g.floats(rotations, "VEC4", 4);
    const int wave_weights = g.floats({0, 0, 1, 0}, "SCALAR", 1);
    const int hop_times = g.floats({0.0f, 1.0f, 2.0f}, "SCALAR", 1);
    const int hop_heights = g.floats({0, 0, 0, 0, 0.5f, 0, 0, 0, 0}, "VEC3", 3);
    g.doc["animations"] = {
        {{"name", "wave"},
         {"samplers",
          {{{"input", wave_times}, {"output", wave_rotations}}, {{"input", wave_times}, {"output", wave_weights}}}},
         {"channels",
          {{{"sampler", 0}, {"target", {{"node", 5}, {"path", "rotation"}}}},
           {{"sampler", 1}, {"target", {{"node", 2}, {"path", "weights"}}}}}}},
        {{"name", "hop"},
         {"samplers", {{{"input", hop_times}, {"output", hop_heights}, {"interpolation", "STEP"}}}},
         {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}}};

    if (format == AvatarFormat::Vrm1) {
        for (int m : {skin_material, cloth_material})
            g.doc["materials"][m]["extensions"]["VRMC_materials_mtoon"] = {
                {"specVersion", "1.0"}, {"shadeColorFactor", {0.6, 0.4, 0.5}}, {"shadingToonyFactor", 0.95}};
        g.doc["extensionsUsed"] = {"KHR_materials_unlit", "VRMC_vrm", "VRMC_materials_mtoon"};
        g.doc["extensions"]["VRMC_vrm"] = {
            {"specVersion", "1.0"},
            {"meta", {{"name", "Inkshade test avatar"}, {"licenseUrl", "https://vrm.dev/licenses/1.0/"}}},
            {"expressions",
             {{"preset",
               {{"happy",
                 {{"morphTargetBinds", {{{"node", 2}, {"index", 0}, {"weight", 1.0}}}}, {"overrideBlink", "block"}}},
                {"blink", {{"morphTargetBinds", {{{"node", 2}, {"index", 1}, {"weight", 1.0}}}}, {"isBinary", true}}}}},
              {"custom", {{"smirk", {{"morphTargetBinds", {{{"node", 2}, {"index", 0}, {"weight", 0.5}}}}}}}}}}};
    } else if (format == AvatarFormat::Vrm0) {
        json properties = json::array();
        for (int m = 0; m < 3; ++m) {
            const json colour = g.doc["materials"][m]["pbrMetallicRoughness"]["baseColorFactor"];
            properties.push_back({{"name", std::vector<std::string>{"skin", "cloth", "ball"}[size_t(m)]},
                                  {"shader", m == ball_material ? "VRM_USE_GLTFSHADER" : "VRM/MToon"},
                                  {"floatProperties", {{"_ShadeToony", 0.9}}},
                                  {"vectorProperties", {{"_Color", colour}, {"_ShadeColor", {0.6, 0.4, 0.5, 1}}}},
                                  {"textureProperties", json::object()}});
        }
        g.doc["extensions"]["VRM"] = {{"specVersion", "0.0"},
                                      {"materialProperties", properties},
                                      {"blendShapeMaster",
                                       {{"blendShapeGroups",
                                         {{{"name", "Joy"},
                                           {"presetName", "joy"},
                                           {"binds", {{{"mesh", head_mesh}, {"index", 0}, {"weight", 100}}}}},
                                          {{"name", "Blink"},
                                           {"presetName", "blink"},
                                           {"isBinary", true},
                                           {"binds", {{{"mesh", head_mesh}, {"index", 1}, {"weight", 100}}}}},
                                          {{"name", "Smirk"},
                                           {"presetName", "unknown"},
                                           {"binds", {{{"mesh", head_mesh}, {"index", 0}, {"weight", 50}}}}}}}}}};
    }
    return g;
}

// Offsets of the parts in the loaded mesh's vertices (load order: body, head, arm, ball).
struct AvatarLayout {
    size_t body = 0, head, arm, ball, end;
};
inline AvatarLayout avatar_layout() {
    AvatarLayout l;
    l.head = avatar_capsule({0, 0.35f, 0}, 0.75f, 0.2f).positions.size() / 3;
    l.arm = l.head + avatar_sphere(glm::vec3(0), kHeadRadius, 12, 16).positions.size() / 3;
    l.ball = l.arm + avatar_arm().positions.size() / 3;
    l.end = l.ball + avatar_sphere(kHandBall, kHandBallRadius, 8, 12).positions.size() / 3;
    return l;
}

}  // namespace inkshade::test
