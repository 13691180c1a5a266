// A base-colour texture on the GPU: GL_SRGB8_ALPHA8 (sampling decodes sRGB to linear, the
// convention of inkshade::Texture and docs/shading.md), full mip chain, trilinear filtering
// plus anisotropy up to 16 where the driver has it (not on llvmpipe: base_texture.cpp), repeat
// wrap (glTF's default and OBJ's).
#pragma once
#include <epoxy/gl.h>

#include "gpu/gl_handle.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::gpu {

class BaseTexture {
public:
    // Rows are uploaded as stored (top row first at t = 0): sample at vec2(u, 1 - v).
    explicit BaseTexture(const Texture& texture);
    // A 1x1 white texel: sRGB 255 decodes to exactly 1.0, so untextured materials of a textured
    // mesh keep their colour bit for bit.
    static BaseTexture white();

    GLuint id() const { return texture_.id(); }
    void bind(GLuint unit) const { glBindTextureUnit(unit, texture_.id()); }

private:
    BaseTexture(int width, int height, const uint8_t* rgba);
    GlTexture texture_;
};

}  // namespace inkshade::gpu
