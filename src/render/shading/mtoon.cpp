#include "inkshade/shading.hpp"

namespace inkshade {
// Defaults are three-vrm 3.5.5's MToonMaterial's (its uniforms' initial values, linear colours),
// so `--shading mtoon` renders what `new MToonMaterial()` renders on three.js r187: shade colour
// black, shift 0, toony 0.9, rim colour black, fresnel power 5, lift 0, rim lighting mix 1,
// no outline (width 0, colour black, lighting mix 1), no emission (black, intensity 1),
// normal scale 1, shading shift texture scale 1, no UV animation (speeds 0), and the threejs
// convention (1/pi light units, sRGB output). A VRM file's materials
// carry the VRMC_materials_mtoon specification's defaults instead (io/gltf_reader.cpp).
// Shadows on: anime-style renderers cast hard shadows from a shadow map.
// use-material-params: a VRM avatar's materials (face, hair, clothes) each carry their own
// MToon values, which one style cannot express, so by default they replace the style's values
// for the parameters a material carries (per material draw, renderer.cpp); off restyles them.
static const ShadingModelRegistration mtoon_model{{
    .name = "mtoon",
    .summary = "MToon 1.0: E*mix(S, C, linearstep(-1+toony, 1-toony, n.l+shift)*shadow) + A*C + rim",
    .fragment = "shading/mtoon.frag",
    .inputs = {shadow_map_input("shadows"), linear_light_input("convention", "threejs")},
    .params =
        {
            color_param("shade-color", glm::vec3(0.0f),
                        "shade colour S, linear (MToon shadeColorFactor)"),
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
            color_param("matcap-color", glm::vec3(1.0f),
                        "matcap texture factor, linear (MToon matcapFactor; the texture comes with a VRM material)"),
            float_param("shading-shift-texture-scale", 1.0f, -100.0f, 100.0f,
                        "scales the shading shift texture's red channel added to the shift (MToon "
                        "shadingShiftTexture.scale; the texture comes with a VRM material)"),
            color_param("emissive", glm::vec3(0.0f),
                        "emitted colour added to the result, linear (glTF emissiveFactor, three-vrm emissive)"),
            float_param("emissive-intensity", 1.0f, 0.0f, 1000.0f,
                        "multiplies emissive (KHR_materials_emissive_strength, three-vrm emissiveIntensity)"),
            float_param(
                "normal-scale", 1.0f, -100.0f, 100.0f,
                "scales the normal map's x and y (glTF normalTexture.scale; the map comes with a VRM material)"),
            float_param(
                "uv-animation-scroll-x-speed", 0.0f, -1000.0f, 1000.0f,
                "uv units a second the textures scroll along u at --time (MToon uvAnimationScrollXSpeedFactor)"),
            float_param("uv-animation-scroll-y-speed", 0.0f, -1000.0f, 1000.0f,
                        "uv units a second along v, downwards in the image (MToon uvAnimationScrollYSpeedFactor)"),
            float_param("uv-animation-rotation-speed", 0.0f, -1000.0f, 1000.0f,
                        "radians a second the textures turn about uv (0.5, 0.5) at --time (MToon "
                        "uvAnimationRotationSpeedFactor)"),
            choice_param("outline-width-mode", {"none", "world-coordinates", "screen-coordinates"}, 0,
                         "outline: none, or back faces pushed out along the normal by outline-width world "
                         "units or by outline-width of the image height at clip w 1 (MToon outlineWidthMode)"),
            float_param("outline-width", 0.0f, 0.0f, 100.0f,
                        "outline width: world units, or a fraction of the image height (MToon outlineWidthFactor)"),
            color_param("outline-color", glm::vec3(0.0f), "outline colour, linear (MToon outlineColorFactor)"),
            float_param("outline-lighting-mix", 1.0f, 0.0f, 1.0f,
                        "0: outline-color as is, 1: times the lit MToon colour (MToon outlineLightingMixFactor)"),
            choice_param("convention", {"seeds", "threejs"}, 1,
                         "threejs: 1/pi light units, three.js's point-light falloff, sRGB output (three-vrm); "
                         "seeds: values as they are, no 1/pi, no sRGB (the display convention of the other models)"),
            compile_time(bool_param("shadows", true, "cast shadows from a shadow map (2048^2, PCF)")),
            float_param("shadow-softness", 1.5f, 0.0f, 4.0f, "PCF filter radius in shadow-map texels"),
            bool_param(
                "use-material-params", true,
                "materials' VRM MToon values (shade colour, shift, toony, rim, outline, emissive, normal scale, UV "
                "animation) and textures replace these per material"),
        },
}};
}  // namespace inkshade
