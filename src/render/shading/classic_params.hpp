// Parameter specs shared by the specular models (phong, blinn-phong).
#pragma once
#include "inkshade/shading.hpp"

namespace inkshade::shading {

inline ParamSpec specular_color_param() {
    return {"specular", ParamType::Color, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f), 0.0f, 1.0f,
            "specular colour k_s (multiplies the light colour)"};
}
inline ParamSpec shininess_param(float default_value) {
    return {"shininess", ParamType::Float, glm::vec4(default_value, 0, 0, 0), 1.0f, 4096.0f,
            "specular exponent"};
}

}  // namespace inkshade::shading
