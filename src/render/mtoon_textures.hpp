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

// three-vrm's colour spaces (MToonMaterialLoaderPlugin's assignTexture, GLTFLoader's for the
// glTF core ones): matcap, rim multiply, shade multiply, shading shift (marked sRGB too, though
// the specification calls it a data texture) and emissive are sRGB colour textures; the outline
// width multiply (green), the normal map and the UV animation mask (blue) are data. The normal
// map's "white when absent" is never read: the shader skips it (u_normal_texture_on).
inline constexpr MtoonTextureSlot kMtoonTextureSlots[] = {
    {"matcap-texture", "u_matcap_texture", true, true},
    {"rim-multiply-texture", "u_rim_multiply_texture", true, false},
    {"outline-width-multiply-texture", "u_outline_width_multiply_texture", false, false},
    {"shade-multiply-texture", "u_shade_multiply_texture", true, false},
    {"shading-shift-texture", "u_shading_shift_texture", true, true},
    {"emissive-texture", "u_emissive_texture", true, false},
    {"normal-texture", "u_normal_texture", false, false},
    {"uv-animation-mask-texture", "u_uv_animation_mask_texture", false, false},
};
// The slot of the normal map, whose presence a draw tells the shader.
inline constexpr int kMtoonNormalTextureSlot = 6;
inline constexpr int kMtoonTextureSlotCount = int(sizeof(kMtoonTextureSlots) / sizeof(kMtoonTextureSlots[0]));

}  // namespace inkshade::render
