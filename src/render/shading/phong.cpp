#include "render/shading/classic_params.hpp"

namespace inkshade {
// Phong 1975, "Illumination for Computer Generated Pictures", with the specular term only where
// n.l > 0 (as in Qu, Chen & Zwicker 2022, "Non-Photorealistic Shading Techniques for Anime-Style
// Rendering", eq. 3); shininess 32 is three.js MeshPhongMaterial's default (30) rounded to 2^5.
static const ShadingModelRegistration phong_model{{
    .name = "phong",
    .summary = "C*(A + E*max(n.l,0)) + k_s*E*max(r.v,0)^shininess, specular only where n.l > 0",
    .fragment = "shading/phong.frag",
    .params = {shading::shininess_param(32.0f), shading::specular_color_param()},
}};
}  // namespace inkshade
