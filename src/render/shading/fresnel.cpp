#include "inkshade/shading.hpp"

namespace inkshade {
// Fresnel (rim glow) shading: 1 - n.v, clamped, raised to a power, times a glow colour and an
// intensity, added to the base shading. 3 is a common rim power (Unity's and Blender's
// Fresnel-rim examples use 2-5) that keeps the glow near the silhouette.
static const ShadingModelRegistration fresnel_model{{
    .name = "fresnel",
    .summary = "rim f = clamp(1-|n.v|,0,1)^power*intensity*glow, added to C*(E*max(n.l,0)+A) or alone",
    .fragment = "shading/fresnel.frag",
    .params =
        {
            float_param("power", 3.0f, 0.1f, 64.0f, "rim exponent: larger keeps the glow closer to the silhouette"),
            float_param("intensity", 1.0f, 0.0f, 16.0f, "rim strength (multiplies the glow)"),
            color_param("glow-color", glm::vec3(1.0f), "rim (glow) colour"),
            choice_param("mode", {"add", "replace"}, 0,
                         "add: rim over Lambert C*(E*max(n.l,0)+A); replace: rim alone over black"),
        },
}};
}  // namespace inkshade
