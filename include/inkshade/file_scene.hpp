// The cameras and lights a model file carries (glTF 2.0 cameras, section 3.10, and the
// KHR_lights_punctual extension), placed in the model's coordinates by their nodes. Plain data:
// `--camera` and `--lights file` turn them into a Camera and a Light (inkshade/scene.hpp).
#pragma once
#include <optional>
#include <string>

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

}  // namespace inkshade
