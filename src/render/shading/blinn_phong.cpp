#include "render/shading/classic_params.hpp"

namespace inkshade {
// max(n.h,0)^(4s) approximates max(r.v,0)^s (Fisher & Woo 1994), hence 128 = 4 x phong's 32.
static const ShadingModelRegistration blinn_phong_model{{
    .name = "blinn-phong",
    .summary = "C*(A + E*max(n.l,0)) + k_s*E*max(n.h,0)^shininess, specular only where n.l > 0",
    .fragment = "shading/blinn-phong.frag",
    .params = {shading::shininess_param(128.0f), shading::specular_color_param()},
}};
}  // namespace inkshade
