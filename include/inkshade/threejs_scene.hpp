// A three.js-like scene description (JSON; docs/threejs.md): one mesh with one material, the
// lights, the camera, the background and an optional OutlineEffect, as a three.js user sets
// them up, so the same scene renders in three.js and in Inkshade. Parsing needs no GL and no
// shading-model registry: values arrive here checked for form (numbers, colours, vectors);
// their ranges are checked where they become model parameters (threejs_scene_style).
#pragma once
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "inkshade/camera.hpp"
#include "inkshade/params.hpp"

namespace inkshade {

struct ThreejsCamera {
    bool orthographic = false;
    glm::vec3 position{0.0f};
    glm::vec3 target{0.0f};  // camera.lookAt(target); default the origin
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_degrees = 50.0f;  // perspective: vertical fov, divided by zoom as three.js does
    float ortho_height = 2.0f;  // orthographic: (top - bottom) / zoom
    float near_plane = 0.1f;
    float far_plane = 2000.0f;
};

struct ThreejsScene {
    std::string source;  // the scene file, for messages
    std::string mesh;    // a path (relative ones resolved against the scene file's folder) or builtin:NAME

    // The material: an Inkshade model (threejs-lambert, ...) and its parameter values by
    // Inkshade name (three.js colours sRGB, as the parameters take them), each with the JSON
    // field it came from ("material.shininess"), for messages. The lights' intensities are
    // model parameters too (light-intensity, ambient-intensity, light-decay, light-distance).
    std::string model;
    ParamValues params;
    std::map<std::string, std::string> param_fields;
    // MToonMaterial's `color` (three-vrm's litFactor), linear: the style's base colour, which
    // multiplies the mesh's colours and texture as litFactor multiplies `map`. Unset: white.
    std::optional<glm::vec3> base_color;

    // OutlineEffect: threejs-outline's thickness, color (linear) and alpha; nullopt = no outline.
    std::optional<ParamValues> outline;

    // Lights, linear colours as three.js holds them. No direct light: light-intensity is 0.
    LightType light_type = LightType::Directional;
    std::optional<glm::vec3> light_position, light_target;  // set with a direct light
    glm::vec3 light_color{1.0f};
    glm::vec3 ambient{0.0f};

    std::optional<ThreejsCamera> camera;           // nullopt: Inkshade's auto-framing
    glm::vec4 background{0.0f, 0.0f, 0.0f, 1.0f};  // as written to the image; three.js clears to black
    std::optional<glm::ivec2> size;                // renderer.setSize
    bool antialias = false;                        // WebGLRenderer's antialias (default off)
};

// Parses scene JSON; `source` names it in errors: InputError("SOURCE: FIELD: problem").
ThreejsScene parse_threejs_scene(std::string_view json, const std::string& source);

// Reads and parses a scene file (at most 1 MiB); relative mesh paths are resolved against its folder.
ThreejsScene load_threejs_scene(const std::string& path);

struct Style;
// The style the scene renders with (in the render library, which holds the shading models):
// its model and parameters checked against their ranges (InputError "SOURCE: FIELD: problem"),
// a threejs-outline line when the scene has an outline, its light colours and background.
Style threejs_scene_style(const ThreejsScene& scene);

}  // namespace inkshade
