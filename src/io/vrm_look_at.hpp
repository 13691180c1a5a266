// VRM look-at (VRM 1.0 VRMC_vrm.lookAt, VRM 0.x firstPerson lookAt*) as three-vrm 3.5.5 applies a
// yaw and pitch: type "bone" turns the eye bones (VRMLookAtBoneApplier), type "expression" sets
// the lookUp / lookDown / lookLeft / lookRight expressions (VRMLookAtExpressionApplier), each
// through range maps from degrees to degrees or weights.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "inkshade/io.hpp"
#include "io/gltf_rest_pose.hpp"
#include "io/vrm_humanoid.hpp"

namespace tinygltf {
class Model;
}

namespace inkshade::io {

struct VrmLookAt {
    // three-vrm's VRMLookAtRangeMap: outputScale x saturate(input / inputMaxValue).
    struct RangeMap {
        double input_max = 90.0, output_scale = 10.0;
        double map(double degrees) const;
    };
    bool expression = false;     // type "expression" (VRM 0.x "BlendShape"), else "bone"
    bool faces_minus_z = false;  // VRM 0.x avatars face -z (three-vrm's faceFront (0, 0, -1))
    RangeMap horizontal_inner, horizontal_outer, vertical_down, vertical_up;
};

// The avatar's look-at, or nullopt when it has none (as three-vrm's VRMLookAtLoaderPlugin: VRM
// 1.0 needs lookAt and expressions, VRM 0.x firstPerson and blendShapeMaster).
std::optional<VrmLookAt> read_vrm_look_at(const tinygltf::Model& model);

// Yaw and pitch in degrees of a look-at rotation (three-vrm-animation's
// VRMLookAtQuaternionProxy: Euler angles in YXZ order, yaw about y, pitch about x).
glm::dvec2 look_at_yaw_pitch(const glm::dquat& q);

// Type "bone": the eye bones' local rotations for the yaw and pitch (node, rotation), from
// their rest rotations.
std::vector<std::pair<int, glm::dquat>> look_at_eye_rotations(const VrmLookAt& look_at, const VrmHumanoid& humanoid,
                                                              const GltfRestPose& rest, glm::dvec2 yaw_pitch);

// Type "expression": the weights of the four look expressions for the yaw and pitch.
std::vector<NamedWeight> look_at_expression_weights(const VrmLookAt& look_at, glm::dvec2 yaw_pitch);

}  // namespace inkshade::io
