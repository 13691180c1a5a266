// Parameter specs shared by the threejs-* models (docs/threejs.md): three.js's material names
// and defaults, and the light intensities three.js keeps on its lights (Inkshade's Light has a
// colour only, so these models carry them).
#pragma once
#include <vector>

#include "inkshade/shading.hpp"

namespace inkshade::shading::threejs {

inline ParamSpec color_param() {
    return srgb_color_param("color", glm::vec3(1.0f), "diffuse colour, sRGB as typed in three.js (default 0xffffff)");
}

// E = light colour x light-intensity (point light: / max(d^light-decay, 0.01)), A = ambient x
// ambient-intensity: three.js's defaults (intensity 1, decay 2, distance 0).
inline std::vector<ParamSpec> light_params() {
    return {float_param("light-intensity", 1.0f, 0.0f, 1e6f,
                        "DirectionalLight/PointLight intensity: E = light colour x intensity (three.js default 1)"),
            float_param("ambient-intensity", 1.0f, 0.0f, 1e6f,
                        "AmbientLight intensity: A = ambient colour x intensity (three.js default 1)"),
            float_param("light-decay", 2.0f, 0.0f, 16.0f,
                        "PointLight decay: E / max(d^decay, 0.01) (three.js default 2, physically correct)"),
            float_param("light-distance", 0.0f, 0.0f, 1e9f,
                        "PointLight distance: light fades to zero there (three.js default 0 = no limit)")};
}

inline std::vector<ParamSpec> emissive_params() {
    return {
        srgb_color_param("emissive", glm::vec3(0.0f), "emitted colour, sRGB as typed in three.js (default 0x000000)"),
        float_param("emissive-intensity", 1.0f, 0.0f, 1e6f, "scales emissive (three.js emissiveIntensity, default 1)")};
}

// The parameters of a lit model: color, then the model's own, then emissive and the lights.
inline std::vector<ParamSpec> lit_params(const std::vector<ParamSpec>& own = {}) {
    std::vector<ParamSpec> p{color_param()};
    p.insert(p.end(), own.begin(), own.end());
    for (const std::vector<ParamSpec>& group : {emissive_params(), light_params()})
        p.insert(p.end(), group.begin(), group.end());
    return p;
}

}  // namespace inkshade::shading::threejs
