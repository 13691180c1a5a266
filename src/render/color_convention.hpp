// The colour convention a frame shades in (docs/shading.md, "Colour conventions"), the one
// place that decides both ends of it, so that a texture comes out as it went in.
//   Display (the default): texels, colours and formula values are used and written as they
//     are, as hand-written GLSL shaders without a gamma step do; a texel's bytes reach the
//     pixel unchanged where the formula leaves C alone.
//   Linear: texels are decoded from sRGB to linear light and the output is sRGB-encoded; with
//     --srgb (RenderOptions::srgb_output), and for a model that declares linear light
//     (ShadingInputKind::LinearLight): the three.js models, mtoon when its "convention" is "threejs".
#pragma once
#include "gpu/base_texture.hpp"
#include "inkshade/renderer.hpp"
#include "inkshade/shading.hpp"

namespace inkshade::render {

enum class ColorConvention { Display, Linear };

// Debug views are Display: they neither sample textures nor encode.
ColorConvention color_convention(const ShadingModel& model, const ParamValues& values, const RenderOptions& options);

// How the convention reads base-colour textures.
inline gpu::Texels texels_of(ColorConvention convention) {
    return convention == ColorConvention::Linear ? gpu::Texels::DecodedFromSrgb : gpu::Texels::AsStored;
}

}  // namespace inkshade::render
