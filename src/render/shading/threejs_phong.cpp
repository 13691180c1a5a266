#include "render/shading/threejs_params.hpp"

namespace inkshade {
// Defaults are MeshPhongMaterial's: specular 0x111111, shininess 30.
static const ShadingModelRegistration threejs_phong_model{{
    .name = "threejs-phong",
    .summary = "three.js r187 MeshPhongMaterial: threejs-lambert + E*max(n.l,0)*F_Schlick*(s+2)/(8pi)*max(n.h,0)^s",
    .fragment = "shading/threejs-phong.frag",
    .inputs = {linear_light_input()},
    .params = shading::threejs::lit_params(
        {srgb_color_param("specular", glm::vec3(float(0x11) / 255.0f),
                          "specular colour S (Fresnel F0), sRGB as typed in three.js (default 0x111111)"),
         float_param("shininess", 30.0f, 0.0f, 10000.0f, "Blinn-Phong exponent s (three.js default 30)")}),
}};
}  // namespace inkshade
