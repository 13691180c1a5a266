// Parameter specs shared by the specular models (phong, blinn-phong).
#pragma once
#include "inkshade/shading.hpp"

namespace inkshade::shading {

inline ParamSpec specular_color_param() {
    return color_param("specular", glm::vec3(0.5f), "specular colour k_s (multiplies the light colour)");
}
inline ParamSpec shininess_param(float default_value) {
    return float_param("shininess", default_value, 1.0f, 4096.0f, "specular exponent");
}

}  // namespace inkshade::shading
