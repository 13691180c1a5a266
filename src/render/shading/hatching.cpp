#include "inkshade/shading.hpp"

namespace inkshade {
// Hatching after Hertzmann & Zorin 2000, "Illustrating Smooth Surfaces": the strokes are the
// `hatch` line type's (src/geometry/hatching.hpp), surface-stable and lit by the render's light,
// drawn by the GPU strokes over a paper fill; `lines --lines hatch` writes the same strokes as SVG.
static const ShadingModelRegistration hatching_model{{
    .name = "hatching",
    .summary = "hatch strokes along principal directions where n.l < tones (the `hatch` lines) over C*mix(1, "
               "E*max(n.l,0) + A, wash)",
    .fragment = "shading/hatching.frag",
    .strokes = "hatch",
    .params =
        {
            float_param("wash", 0.0f, 0.0f, 1.0f, "share of the Lambertian tone in the paper fill (0 = plain paper)"),
            color_param("color", glm::vec3(0.0f), "stroke colour"),
            float_param("width", 0.75f, 0.0f, 64.0f, "stroke width in pixels"),
            float_param("opacity", 1.0f, 0.0f, 1.0f, "stroke opacity"),
            float_param("spacing", 0.0f, 0.0f, 1e9f,
                        "world distance between strokes of the lightest level; 0 = 1.5% of the bounding-box diagonal / "
                        "density"),
            float_param("density", 1.0f, 0.01f, 100.0f, "with spacing 0: strokes this many times denser"),
            int_param("levels", 2, 1, 4, "density levels per direction, each adding strokes halfway between"),
            bool_param("cross", true, "also strokes across the first direction (cross-hatching)"),
            list_param("tones", {0.8f, 0.6f, 0.4f, 0.2f}, 8, 0.0f, 1.0f,
                       "a level's strokes are drawn where n.l is below its value (as the hatch line type)"),
            float_param("fade", 0.05f, 0.0f, 1.0f, "strokes fade in over this much tone below their threshold"),
            float_param("thin", 0.25f, 0.0f, 1.0f, "level k > 0 fades out where n.v < thin*2^(k-1)"),
            int_param("smoothing", 30, 0, 1000, "smoothing iterations of the principal-direction field"),
            int_param("seed", 0, 0, 1000000, "order in which free seeds are tried (and the strokes' noise and jitter)"),
        },
}};
}  // namespace inkshade
