#include "render/shading/threejs_params.hpp"

namespace inkshade {
// MeshToonMaterial without a gradient map: 0.7 below half-Lambert 0.7 (n.l = 0.4), 1 above. The
// gradient map is a list of texel values (DataTexture of a RedFormat ramp, nearest filtering);
// use-gradient-map switches it on at compile time, as three.js's USE_GRADIENTMAP does.
static const ShadingModelRegistration threejs_toon_model{{
    .name = "threejs-toon",
    .summary =
        "three.js r187 MeshToonMaterial: sRGB(C/pi*(E*g(0.5*n.l + 0.5) + A) + emissive), g from the gradient map",
    .fragment = "shading/threejs-toon.frag",
    .inputs = {linear_light_input()},
    .params = shading::threejs::lit_params(
        {compile_time(bool_param("use-gradient-map", false,
                                 "shade with gradient-map (three.js gradientMap); off: three.js's default two tones")),
         list_param("gradient-map", {0.35f, 0.7f, 1.0f}, 32, 0.0f, 1.0f,
                    "gradient map texels from the dark end (u = 0) to the lit end, values 0-1, nearest filtering")}),
}};
}  // namespace inkshade
