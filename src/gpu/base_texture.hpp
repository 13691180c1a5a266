// A base-colour texture on the GPU, readable two ways (inkshade::Texture's bytes are sRGB): as
// stored (a GL_RGBA8 view, byte / 255) or decoded to linear light (the GL_SRGB8_ALPHA8 storage),
// chosen per draw by the frame's colour convention (render/color_convention.hpp,
// docs/shading.md). Both share one full mip chain, built in linear light, read as the texture's
// sampler says (wrap, filters; anisotropy up to 16 where the sampler asks for it and the driver
// has it, not on llvmpipe: base_texture.cpp).
#pragma once
#include <epoxy/gl.h>

#include "gpu/gl_handle.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::gpu {

// How a sample reads the texel bytes.
enum class Texels {
    AsStored,         // byte / 255: the display convention
    DecodedFromSrgb,  // the sRGB EOTF of byte / 255, linear light: the linear convention
};

class BaseTexture {
public:
    // Rows are uploaded as stored (top row first at t = 0): sample at vec2(u, 1 - v).
    explicit BaseTexture(const Texture& texture);
    // A 1x1 white texel: 255 is exactly 1.0 read either way, so untextured materials of a
    // textured mesh keep their colour bit for bit.
    static BaseTexture white();
    // A 1x1 black texel (alpha 1): an absent texture that adds (MToon's matcap) adds nothing.
    static BaseTexture black();

    void bind(GLuint unit, Texels texels) const {
        glBindTextureUnit(unit, texels == Texels::AsStored ? stored_.id() : srgb_.id());
    }

private:
    BaseTexture(int width, int height, const uint8_t* rgba, const TextureSampler& sampler);
    GlTexture srgb_;        // the storage, GL_SRGB8_ALPHA8: sampling decodes
    GlTextureView stored_;  // the same texels as GL_RGBA8: sampling reads the bytes
};

}  // namespace inkshade::gpu
