#include "inkshade/shading.hpp"

namespace inkshade {
// Defaults are those of the VRM MToon 1.0 specification (VRMC_materials_mtoon; formula in
// docs/shading.md): shade colour 0, shift 0, toony 0.9, rim colour 0, fresnel power 5, lift 0,
// rim lighting mix 1. Shadows on: anime-style renderers cast hard shadows from a shadow map.
// use-material-params: a VRM avatar's materials (face, hair, clothes) each carry their own
// MToon values, which one style cannot express, so by default they replace the style's values
// for the parameters a material carries (per material draw, renderer.cpp); off restyles them.
static const ShadingModelRegistration mtoon_model{{
    .name = "mtoon",
    .summary = "MToon 1.0: E*mix(S, C, linearstep(-1+toony, 1-toony, n.l+shift)*shadow) + A*C + rim",
    .fragment = "shading/mtoon.frag",
    .shadow_map = true,
    .params =
        {
            color_param("shade-color", glm::vec3(0.0f), "shade colour S (MToon shadeColorFactor)"),
            float_param("shading-shift", 0.0f, -1.0f, 1.0f,
                        "shift added to n.l before the toon step (MToon shadingShiftFactor)"),
            float_param("shading-toony", 0.9f, 0.0f, 1.0f,
                        "toony-ness: 1 = hard terminator, 0 = smooth (MToon shadingToonyFactor)"),
            color_param("rim-color", glm::vec3(0.0f), "rim colour (MToon parametricRimColorFactor; black = no rim)"),
            float_param("rim-fresnel-power", 5.0f, 0.0f, 100.0f,
                        "rim exponent on 1 - n.v (MToon parametricRimFresnelPowerFactor)"),
            float_param("rim-lift", 0.0f, 0.0f, 1.0f,
                        "added to 1 - n.v before the power (MToon parametricRimLiftFactor)"),
            float_param("rim-lighting-mix", 1.0f, 0.0f, 1.0f,
                        "0: rim unlit, 1: rim scaled by E + A (MToon rimLightingMixFactor)"),
            choice_param("convention", {"seeds", "threejs"}, 0,
                         "seeds: values as they are, no 1/pi, no sRGB (Inkshade's default convention); "
                         "threejs: 1/pi light units and sRGB output (three-vrm)"),
            compile_time(bool_param("shadows", true, "cast shadows from a shadow map (2048^2, PCF)")),
            float_param("shadow-softness", 1.5f, 0.0f, 4.0f, "PCF filter radius in shadow-map texels"),
            bool_param("use-material-params", true,
                       "materials' VRM MToon values (shade colour, shift, toony, rim) replace these per material"),
        },
}};
}  // namespace inkshade
