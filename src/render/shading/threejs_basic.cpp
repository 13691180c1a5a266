#include "render/shading/threejs_params.hpp"

namespace inkshade {
static const ShadingModelRegistration threejs_basic_model{{
    .name = "threejs-basic",
    .summary = "three.js r187 MeshBasicMaterial, unlit: sRGB(C*color)",
    .fragment = "shading/threejs-basic.frag",
    .inputs = {linear_light_input()},
    .params = {shading::threejs::color_param()},
}};
}  // namespace inkshade
