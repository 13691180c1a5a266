#include "render/shading/threejs_params.hpp"

namespace inkshade {
static const ShadingModelRegistration threejs_lambert_model{{
    .name = "threejs-lambert",
    .summary = "three.js r187 MeshLambertMaterial: sRGB(C/pi*(E*max(n.l,0) + A) + emissive)",
    .fragment = "shading/threejs-lambert.frag",
    .inputs = {linear_light_input()},
    .params = shading::threejs::lit_params(),
}};
}  // namespace inkshade
