#include "gpu/base_texture.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#include "inkshade/error.hpp"

namespace inkshade::gpu {

namespace {

// The texture itself, after checking that its pixels match its size (nothing is read past them).
const Texture& checked(const Texture& texture) {
    if (texture.width <= 0 || texture.height <= 0 ||
        texture.rgba.size() != size_t(texture.width) * size_t(texture.height) * 4)
        throw RuntimeError("texture " + texture.source + ": pixel data does not match its size");
    return texture;
}

// Anisotropic filtering where the driver has it, except on llvmpipe: there (Mesa 22.3) any
// maximum anisotropy above 1 also blurs magnified textures (a 2x2 texture seen at 33 px per
// texel read 35% of its neighbours at a texel's centre: tests/render/texture_test.cpp).
float max_anisotropy() {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (renderer && std::strstr(renderer, "llvmpipe")) return 1.0f;
    if (epoxy_gl_version() < 46 && !epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic") &&
        !epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic"))
        return 1.0f;
    GLfloat max = 1.0f;
    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &max);
    return std::min(16.0f, max);
}

GLenum wrap_mode(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
        case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
        case TextureWrap::Repeat: break;
    }
    return GL_REPEAT;
}

GLenum min_filter(const TextureSampler& s) {
    const bool nearest = s.min == TextureFilter::Nearest;
    if (!s.mipmap) return nearest ? GL_NEAREST : GL_LINEAR;
    if (*s.mipmap == TextureFilter::Nearest) return nearest ? GL_NEAREST_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_NEAREST;
    return nearest ? GL_NEAREST_MIPMAP_LINEAR : GL_LINEAR_MIPMAP_LINEAR;
}

}  // namespace

BaseTexture::BaseTexture(const Texture& texture)
    : BaseTexture(checked(texture).width, texture.height, texture.rgba.data(), texture.sampler) {}

BaseTexture BaseTexture::white() {
    const uint8_t texel[4] = {255, 255, 255, 255};
    return BaseTexture(1, 1, texel, {});
}

BaseTexture BaseTexture::black() {
    const uint8_t texel[4] = {0, 0, 0, 255};
    return BaseTexture(1, 1, texel, {});
}

BaseTexture::BaseTexture(int width, int height, const uint8_t* rgba, const TextureSampler& sampler)
    : srgb_(GlTexture::create(GL_TEXTURE_2D)) {
    const GLsizei levels = GLsizei(std::bit_width(unsigned(std::max(width, height))));
    glTextureStorage2D(srgb_.id(), levels, GL_SRGB8_ALPHA8, width, height);
    // RGBA8 rows are 4-byte aligned, as the default unpack alignment expects.
    glTextureSubImage2D(srgb_.id(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    // Built through the sRGB format, so each level averages in linear light: a minified
    // black/white checker is 0.5 of the light (byte 188), read either way, as a screen shows it.
    glGenerateTextureMipmap(srgb_.id());
    stored_ = GlTextureView::create(srgb_.id(), GLenum(GL_RGBA8), GLuint(levels));
    // A view has its own sampling state: both get the same. A minification filter without
    // mipmaps reads level 0 only, which is what three.js's texture without mipmaps gives.
    const float anisotropy = sampler.anisotropic ? max_anisotropy() : 1.0f;
    for (const GLuint id : {srgb_.id(), stored_.id()}) {
        glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GLint(min_filter(sampler)));
        glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, sampler.mag == TextureFilter::Nearest ? GL_NEAREST : GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_WRAP_S, GLint(wrap_mode(sampler.wrap_s)));
        glTextureParameteri(id, GL_TEXTURE_WRAP_T, GLint(wrap_mode(sampler.wrap_t)));
        if (anisotropy > 1.0f) glTextureParameterf(id, GL_TEXTURE_MAX_ANISOTROPY, anisotropy);
    }
}

}  // namespace inkshade::gpu
