#include "render/shadow_map.hpp"

#include "inkshade/error.hpp"

namespace inkshade::render {

ShadowMap::ShadowMap(int size)
    : size_(size), depth_(gpu::GlTexture::create(GL_TEXTURE_2D)), fbo_(gpu::GlFramebuffer::create()) {
    const GLuint depth = depth_.id();
    glTextureStorage2D(depth, 1, GL_DEPTH_COMPONENT32F, size, size);
    glTextureParameteri(depth, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(depth, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(depth, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(depth, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(depth, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(depth, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth, 0);
    glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
    glNamedFramebufferReadBuffer(fbo_.id(), GL_NONE);
    if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError("cannot create the shadow-map framebuffer");
}

}  // namespace inkshade::render
