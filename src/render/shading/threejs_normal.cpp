#include "inkshade/shading.hpp"

namespace inkshade {
// A material in three.js, not an Inkshade debug view: it is listed with the shading models.
static const ShadingModelRegistration threejs_normal_model{{
    .name = "threejs-normal",
    .summary = "three.js r187 MeshNormalMaterial: view-space normal 0.5*n + 0.5, not sRGB-encoded",
    .fragment = "shading/threejs-normal.frag",
}};
}  // namespace inkshade
