#include "io/vrm_look_at.hpp"

#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"
#include "io/gltf_value_member.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace inkshade::io {

namespace {

double number_or(const tinygltf::Value& v, double fallback) {
    return v.IsNumber() && std::isfinite(v.GetNumberAsDouble()) ? v.GetNumberAsDouble() : fallback;
}

// VRMLookAtLoaderPlugin's INPUT_MAX_VALUE_MINIMUM.
constexpr double kInputMaxMinimum = 0.01;

// A range map: VRM 1.0 inputMaxValue / outputScale, VRM 0.x xRange / yRange.
VrmLookAt::RangeMap range_map(const tinygltf::Value& v, const char* input, const char* output, double scale) {
    return {std::max(number_or(member(v, input), 90.0), kInputMaxMinimum), number_or(member(v, output), scale)};
}

// A rotation from Euler angles (radians) in three.js's YXZ order.
glm::dquat euler_yxz(double x, double y) {
    return glm::angleAxis(y, glm::dvec3(0, 1, 0)) * glm::angleAxis(x, glm::dvec3(1, 0, 0));
}

}  // namespace

double VrmLookAt::RangeMap::map(double degrees) const {
    return output_scale * std::clamp(degrees / input_max, 0.0, 1.0);
}

std::optional<VrmLookAt> read_vrm_look_at(const tinygltf::Model& model) {
    VrmLookAt out;
    if (auto v1 = model.extensions.find("VRMC_vrm"); v1 != model.extensions.end()) {
        const tinygltf::Value& l = member(v1->second, "lookAt");
        if (!l.IsObject() || !member(v1->second, "expressions").IsObject()) return std::nullopt;
        out.expression = member(l, "type").IsString() && member(l, "type").Get<std::string>() == "expression";
        const double scale = out.expression ? 1.0 : 10.0;
        out.horizontal_inner = range_map(member(l, "rangeMapHorizontalInner"), "inputMaxValue", "outputScale", scale);
        out.horizontal_outer = range_map(member(l, "rangeMapHorizontalOuter"), "inputMaxValue", "outputScale", scale);
        out.vertical_down = range_map(member(l, "rangeMapVerticalDown"), "inputMaxValue", "outputScale", scale);
        out.vertical_up = range_map(member(l, "rangeMapVerticalUp"), "inputMaxValue", "outputScale", scale);
        return out;
    }
    if (auto v0 = model.extensions.find("VRM"); v0 != model.extensions.end()) {
        const tinygltf::Value& f = member(v0->second, "firstPerson");
        if (!f.IsObject() || !member(v0->second, "blendShapeMaster").IsObject()) return std::nullopt;
        out.expression =
            member(f, "lookAtTypeName").IsString() && member(f, "lookAtTypeName").Get<std::string>() == "BlendShape";
        out.faces_minus_z = true;
        const double scale = out.expression ? 1.0 : 10.0;
        out.horizontal_inner = range_map(member(f, "lookAtHorizontalInner"), "xRange", "yRange", scale);
        out.horizontal_outer = range_map(member(f, "lookAtHorizontalOuter"), "xRange", "yRange", scale);
        out.vertical_down = range_map(member(f, "lookAtVerticalDown"), "xRange", "yRange", scale);
        out.vertical_up = range_map(member(f, "lookAtVerticalUp"), "xRange", "yRange", scale);
        return out;
    }
    return std::nullopt;
}

glm::dvec2 look_at_yaw_pitch(const glm::dquat& q) {
    // three.js Euler.setFromRotationMatrix, order YXZ (m[column][row] here).
    const glm::dmat3 m = glm::mat3_cast(glm::normalize(q));
    const double m23 = std::clamp(m[2][1], -1.0, 1.0);
    const double x = std::asin(-m23);
    const double y = std::abs(m23) < 0.9999999 ? std::atan2(m[2][0], m[2][2]) : std::atan2(-m[0][2], m[0][0]);
    return glm::degrees(glm::dvec2(y, x));
}

std::vector<std::pair<int, glm::dquat>> look_at_eye_rotations(const VrmLookAt& look_at, const VrmHumanoid& humanoid,
                                                              const GltfRestPose& rest, glm::dvec2 yaw_pitch) {
    const double yaw = yaw_pitch.x, pitch = yaw_pitch.y;
    // VRMLookAtBoneApplier._getWorldFaceFrontQuat: identity, or half a turn about y for -z.
    const glm::dquat front = look_at.faces_minus_z ? euler_yxz(0.0, std::numbers::pi) : glm::dquat(1, 0, 0, 0);
    std::vector<std::pair<int, glm::dquat>> out;
    for (const bool left : {true, false}) {
        const int node = humanoid.node(left ? "leftEye" : "rightEye");
        if (node < 0) continue;
        const double x = pitch < 0.0 ? -look_at.vertical_down.map(-pitch) : look_at.vertical_up.map(pitch);
        // The left eye turns outwards for positive yaw, the right one inwards.
        const VrmLookAt::RangeMap& negative = left ? look_at.horizontal_inner : look_at.horizontal_outer;
        const VrmLookAt::RangeMap& positive = left ? look_at.horizontal_outer : look_at.horizontal_inner;
        const double y = yaw < 0.0 ? -negative.map(-yaw) : positive.map(yaw);
        const glm::dquat normalized = front * euler_yxz(glm::radians(x), glm::radians(y)) * glm::inverse(front);
        const glm::dquat p = rest.parent_world_rotation(size_t(node));
        out.emplace_back(node, glm::inverse(p) * normalized * p * rest.rotation[size_t(node)]);
    }
    return out;
}

std::vector<NamedWeight> look_at_expression_weights(const VrmLookAt& look_at, glm::dvec2 yaw_pitch) {
    const double yaw = yaw_pitch.x, pitch = yaw_pitch.y;
    // VRMLookAtExpressionApplier.applyYawPitch, as written there (lookLeft and lookRight both
    // take the outer horizontal map).
    std::vector<NamedWeight> out;
    if (pitch < 0.0)
        out = {{"lookDown", 0.0f}, {"lookUp", float(look_at.vertical_up.map(-pitch))}};
    else
        out = {{"lookUp", 0.0f}, {"lookDown", float(look_at.vertical_down.map(pitch))}};
    if (yaw < 0.0) {
        out.push_back({"lookLeft", 0.0f});
        out.push_back({"lookRight", float(look_at.horizontal_outer.map(-yaw))});
    } else {
        out.push_back({"lookRight", 0.0f});
        out.push_back({"lookLeft", float(look_at.horizontal_outer.map(yaw))});
    }
    return out;
}

}  // namespace inkshade::io
