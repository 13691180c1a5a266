// The textures of an MToon material beside its base colour (Material::mtoon_textures), each in
// a texture unit of its own after the base colour's, and what an absent one reads as, so a
// material without it renders as three-vrm renders it without (no #ifdef per texture).
#pragma once
#include <cstdint>

namespace inkshade::render {

struct MtoonTextureSlot {
    const char* name;        // the key in Material::mtoon_textures
    const char* sampler;     // the GLSL sampler (shaders/shading/mtoon.frag, mtoon_outline.glsl)
    bool color;              // a colour texture, read in the frame's colour convention; else data, as stored
    bool black_when_absent;  // adds (matcap): black; multiplies: white
};

// three-vrm's colour spaces: matcap and rim multiply are sRGB colour textures, the outline
// width multiply (its green channel) is data.
inline constexpr MtoonTextureSlot kMtoonTextureSlots[] = {
    {"matcap-texture", "u_matcap_texture", true, true},
    {"rim-multiply-texture", "u_rim_multiply_texture", true, false},
    {"outline-width-multiply-texture", "u_outline_width_multiply_texture", false, false},
};
inline constexpr int kMtoonTextureSlotCount = int(sizeof(kMtoonTextureSlots) / sizeof(kMtoonTextureSlots[0]));

}  // namespace inkshade::render
