#include "inkshade/shading.hpp"

namespace inkshade {
// Defaults reproduce the five-band cel shading of Qu, Chen & Zwicker 2022, "Non-Photorealistic
// Shading Techniques for Anime-Style Rendering", eq. 4 (five equal bands on half-Lambert, plus
// ambient). The presets (src/styles/presets/) give three classic settings: cel-000 is that
// five-band shading with hard edges, cel-002 the three-tone 1.0 / 0.66 / 0.33 quantisation of
// the Lambert cosine, cel-004 three bands with a hard Blinn-Phong highlight and a rim light.
static const ShadingModelRegistration cel_model{{
    .name = "cel",
    .summary = "C*(E*mix(shade, 1, level(d)) + A), level = levels[first i with d > thresholds[i]]; "
               "optional hard Blinn-Phong highlight and rim",
    .fragment = "shading/cel.frag",
    .params =
        {
            choice_param("driver", {"half-lambert", "ndotl"}, 0,
                         "band driver d: 0.5*n.l + 0.5 (half-Lambert, Qu et al. 2022) or max(n.l, 0) (Lambert cosine)"),
            list_param("thresholds", {0.8f, 0.6f, 0.4f, 0.2f}, 7, 0.0f, 1.0f,
                       "band thresholds on d, descending (Qu et al. 2022: 0.8,0.6,0.4,0.2)"),
            list_param("levels", {1.0f, 0.75f, 0.5f, 0.25f, 0.0f}, 8, 0.0f, 1.0f,
                       "light level per band, one more than thresholds; the last is used below "
                       "every threshold (Qu et al. 2022: 1,0.75,0.5,0.25,0)"),
            color_param("shade-color", glm::vec3(0.0f),
                        "colour of light level 0 instead of black: lit = mix(shade, 1, level)"),
            float_param("smoothing", 1.0f, 0.0f, 16.0f,
                        "edge blend width in units of fwidth (pixels); 0 = hard edges (classic cel shading)"),
            compile_time(
                bool_param("specular", false, "hard Blinn-Phong highlight: max(n.h, 0)^shininess above a threshold")),
            float_param("shininess", 32.0f, 1.0f, 4096.0f, "highlight exponent p of max(n.h, 0)^p"),
            float_param("specular-threshold", 0.5f, 0.0f, 1.0f, "highlight where max(n.h, 0)^p exceeds this"),
            color_param("specular-color", glm::vec3(1.0f), "highlight colour (multiplies E)"),
            compile_time(bool_param("rim", false, "rim light on the lit side near the silhouette")),
            color_param("rim-color", glm::vec3(1.0f), "rim colour (multiplies E)"),
            float_param("rim-threshold", 0.716f, 0.0f, 1.0f,
                        "rim where (1 - n.v) * max(n.l, 0)^rim-power exceeds this (Roystan's toon tutorial: 0.716)"),
            float_param("rim-power", 0.1f, 0.0f, 16.0f,
                        "exponent on n.l confining the rim to the lit side (Roystan's toon tutorial: 0.1)"),
        },
}};
}  // namespace inkshade
