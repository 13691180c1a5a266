// Camera and light: plain data plus auto-framing, no GL.
#pragma once
#include <optional>
#include <string_view>
#include <span>

#include <glm/glm.hpp>

#include "inkshade/mesh.hpp"

namespace inkshade {

struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_degrees = 30.0f;  // vertical field of view (perspective)
    bool orthographic = false;
    float ortho_height = 2.0f;  // world-space height of the view (orthographic)
    float near_plane = 0.1f;
    float far_plane = 100.0f;

    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
};

// The axis that points up in a model's coordinates: +y for glTF (by definition), three.js and
// most OBJ files; +z for many CAD and Blender exports.
enum class UpAxis { PosX, NegX, PosY, NegY, PosZ, NegZ };

// The rotation taking the camera math's frame (+y up, azimuth 0 looking from +z) to a model
// whose up is `axis`: +y goes to `axis`, and the front (+z) to the direction a viewer of such
// files calls front (for +z up: -y, as in Blender's front view). A signed permutation.
glm::mat3 up_axis_rotation(UpAxis axis);

// The axis named x, y, z, -x, -y or -z (a leading + is allowed), or nothing; and its name.
std::optional<UpAxis> up_axis_named(std::string_view name);
const char* up_axis_name(UpAxis axis);

// How the user places the camera; anything unset is chosen by auto-framing.
struct CameraOptions {
    std::optional<float> azimuth_degrees;    // about +y; 0 looks from +z towards -z, 90 from +x
    std::optional<float> elevation_degrees;  // above the horizontal plane
    std::optional<float> distance;           // eye to target, world units
    std::optional<glm::vec3> eye, target, up;
    float fov_degrees = 30.0f;
    bool orthographic = false;
    // Fixed instead of fitted to the model (a three.js camera's near, far, top - bottom).
    std::optional<float> near_plane, far_plane;
    std::optional<float> ortho_height;
    // Azimuth turns about this axis and elevation rises towards it; the default up vector is it.
    // Eye, target and up, when given, are in the model's coordinates whatever the axis.
    // Unset: the style's up-axis (make_scene), else +y.
    std::optional<UpAxis> up_axis;
    // Auto-framing leaves this fraction of the image's width and height free on each side of
    // the model, on the axis that limits it; [0, 0.5).
    float margin = 0.05f;
};

// Default view angles of auto-framing: a three-quarter view from slightly above.
constexpr float kDefaultAzimuth = 35.0f;
constexpr float kDefaultElevation = 20.0f;

// Frames a model tightly. Seen from the view direction (azimuth and elevation, or the eye), the
// projection of `points` (the model's vertices; none: the eight corners of its bounding `box`,
// which fill less of the image when the model is round) spans 1 - 2 margin of the image's
// width or height, whichever limits, and is centred on both axes. Perspective: the eye moves
// along and across the view direction (the target becomes the point of the view axis nearest
// the box centre); with a target given, only along it, so the farthest point meets the margin.
// Orthographic: the view height fits, and the view axis moves across to centre the model unless
// eye or target is given. A given eye, distance or ortho height is kept; near/far enclose the
// bounding sphere. Linear in the number of points.
Camera frame_camera(const BoundingBox& box, const CameraOptions& options, float aspect,
                    std::span<const glm::vec3> points = {});

// Near and far planes that enclose the bounding sphere of `box` from the current eye, as
// frame_camera sets them (used again after the camera moved).
void fit_clip_planes(Camera& camera, const BoundingBox& box);

// Spot: a point light whose cone points from position to target (a model file's light).
enum class LightType { Directional, Point, Spot };

// Whose light shines on the model: the style's key light, placed by the light options
// (default_light), or the model file's first light (glTF KHR_lights_punctual, FileLight;
// Inkshade shades with one light).
enum class LightSource { Style, File };

struct Light {
    LightType type = LightType::Directional;
    glm::vec3 position{1.0f, 1.0f, 1.0f};  // world; directional lights shine from position to target
    glm::vec3 target{0.0f};
    glm::vec3 color{0.9f};
    glm::vec3 ambient{0.1f};
    // Spot cone: full light within cos_inner of the axis, none outside cos_outer, smoothstep
    // between (three.js getSpotAttenuation; KHR_lights_punctual inner and outer cone angles).
    float cos_inner = 1.0f, cos_outer = 0.0f;
    // E = color x intensity in every model (three.js's Light.intensity; lets E exceed 1).
    float intensity = 1.0f;
    // Point and spot lights in physical units (physical_falloff: mtoon's threejs convention):
    // E x 1 / max(d^decay, 0.01) x (clamp(1 - (d / range)^4, 0, 1))^2 (range 0: no window),
    // three.js's getDistanceAttenuation with PointLight.decay and .distance. Off (display
    // units): E reaches every point as it is, as three.js's legacy lights with distance 0 did.
    // The threejs-* models take decay and distance as parameters of their own.
    bool physical_falloff = false;
    float decay = 2.0f;
    float range = 0.0f;
    // Unit vector towards the light at world point p (l in the shading formulas, docs/shading.md).
    glm::vec3 direction_to_light(const glm::vec3& p) const;
};

// The default light: above, left and in front of the camera (a classic key light),
// at three bounding radii from the model centre.
Light default_light(const BoundingBox& box, const Camera& camera);

}  // namespace inkshade
