// The cameras and lights a model file carries (glTF 2.0 cameras, section 3.10, and the
// KHR_lights_punctual extension), placed in the model's coordinates by their nodes, and the names
// its pose can be given by (animations, morph targets, VRM expressions). Plain data: `--camera`
// and `--lights file` turn the first into a Camera and a Light (inkshade/scene.hpp); `inkshade
// info` lists the names that `--animation`, `--morph` and `--expression` take.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace inkshade {

// Where a node puts a camera or light: its global transform applied to the origin and to the
// local axes, scale ignored (glTF 2.0 section 3.10.1; KHR_lights_punctual "Adding Light
// Instances to Nodes"). Unit vectors.
struct NodePlacement {
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};  // local -Z: where a camera looks and a light shines
    glm::vec3 up{0.0f, 1.0f, 0.0f};        // local +Y: the top of a camera's view
};

// One node's camera. Several nodes may share a camera; each is listed.
struct FileCamera {
    std::string name;  // the camera's name, else its node's, else "camera N" (N: glTF index)
    bool orthographic = false;
    float yfov_degrees = 45.0f;         // perspective: vertical field of view
    std::optional<float> aspect_ratio;  // perspective: width / height; unset: the image's
    float xmag = 1.0f, ymag = 1.0f;     // orthographic: half the view's width and height
    float znear = 0.1f;
    std::optional<float> zfar;  // unset: infinite (perspective only)
    NodePlacement placement;
};

enum class FileLightType { Directional, Point, Spot };

// One node's light (KHR_lights_punctual), in the extension's units.
struct FileLight {
    std::string name;  // the light's name, else its node's, else "light N"
    FileLightType type = FileLightType::Directional;
    glm::vec3 color{1.0f};                // linear RGB
    float intensity = 1.0f;               // lux (directional) or candela (point, spot)
    std::optional<float> range;           // point, spot: where the light reaches zero; unset: infinite
    float inner_cone_angle = 0.0f;        // spot, radians from the axis: full intensity inside
    float outer_cone_angle = 0.7853982f;  // spot: no light outside (default pi/4)
    NodePlacement placement;              // directional and spot lights shine along forward
};

// One glTF animation (section 3.11), as `--animation` names it (its name, else its index).
struct FileAnimation {
    std::string name;               // may be empty
    std::optional<float> duration;  // seconds to the last keyframe, as three.js's AnimationClip
                                    // counts it; unset when its keyframes cannot be read
};

// One VRM expression, as `--expression` names it.
struct FileExpression {
    std::string name;     // VRM 1.0 name (VRM 0.x presets renamed as three-vrm does: joy -> happy)
    bool preset = false;  // a VRM 1.0 preset (happy, blink, aa, ...), else a custom expression
};

// The names a glTF/VRM file's pose takes (empty for other formats).
struct FilePoseNames {
    std::vector<FileAnimation> animations;   // in file order
    std::vector<std::string> morph_targets;  // mesh.extras.targetNames, each name once, in file order
    std::vector<FileExpression> expressions;
    size_t spring_joints = 0;  // VRM spring bone joints (they move with the time)
    bool empty() const {
        return animations.empty() && morph_targets.empty() && expressions.empty() && spring_joints == 0;
    }
};

}  // namespace inkshade
