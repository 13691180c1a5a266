#include "render/gbuffer.hpp"

#include "inkshade/error.hpp"

namespace inkshade::render {

namespace {

gpu::GlTexture make_texture(int width, int height, GLenum format) {
    gpu::GlTexture t = gpu::GlTexture::create(GL_TEXTURE_2D);
    glTextureStorage2D(t.id(), 1, format, width, height);
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

}  // namespace

GBuffer::GBuffer(int width, int height)
    : width_(width),
      height_(height),
      surface_(make_texture(width, height, GL_RGBA32F)),
      face_normal_(make_texture(width, height, GL_RGBA8_SNORM)),
      depth_(gpu::GlRenderbuffer::create()),
      fbo_(gpu::GlFramebuffer::create()) {
    glNamedRenderbufferStorage(depth_.id(), GL_DEPTH_COMPONENT32F, width, height);
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, surface_.id(), 0);
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, face_normal_.id(), 0);
    glNamedFramebufferRenderbuffer(fbo_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
    if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError("cannot create the line passes' G-buffer (out of memory?)");
}

void GBuffer::bind_for_drawing(bool face_normals) const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbo_.id(), face_normals ? 2 : 1, buffers);
    const GLfloat zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    if (face_normals) glClearBufferfv(GL_COLOR, 1, zero);
    const GLfloat one = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &one);
}

void GBuffer::bind_textures(GLuint surface_unit, GLuint face_normal_unit) const {
    glBindTextureUnit(surface_unit, surface_.id());
    glBindTextureUnit(face_normal_unit, face_normal_.id());
}

}  // namespace inkshade::render
