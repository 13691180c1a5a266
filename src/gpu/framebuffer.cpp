#include "gpu/framebuffer.hpp"

#include <algorithm>
#include <string>

#include "inkshade/error.hpp"

namespace inkshade::gpu {

Framebuffer::Framebuffer(int width, int height, int samples)
    : width_(width), height_(height), samples_(std::max(1, samples)) {
    GLint max_size = 0, max_samples = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    if (width <= 0 || height <= 0 || width > max_size || height > max_size)
        throw RuntimeError("image size " + std::to_string(width) + "x" + std::to_string(height) +
                           " is outside what this OpenGL supports (1.." + std::to_string(max_size) + ")");
    samples_ = std::min(samples_, std::max(1, int(max_samples)));

    msaa_color_ = GlRenderbuffer::create();
    msaa_depth_ = GlRenderbuffer::create();
    if (samples_ > 1) {
        glNamedRenderbufferStorageMultisample(msaa_color_.id(), samples_, GL_RGBA8, width, height);
        glNamedRenderbufferStorageMultisample(msaa_depth_.id(), samples_, GL_DEPTH32F_STENCIL8, width, height);
    } else {
        // Multisample storage with 1 sample may still be multisampled (llvmpipe rounds 1 up
        // to 4): samples = 1 must mean no MSAA, so use plain storage.
        glNamedRenderbufferStorage(msaa_color_.id(), GL_RGBA8, width, height);
        glNamedRenderbufferStorage(msaa_depth_.id(), GL_DEPTH32F_STENCIL8, width, height);
    }
    msaa_fbo_ = GlFramebuffer::create();
    glNamedFramebufferRenderbuffer(msaa_fbo_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_color_.id());
    glNamedFramebufferRenderbuffer(msaa_fbo_.id(), GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, msaa_depth_.id());

    resolve_color_ = GlRenderbuffer::create();
    glNamedRenderbufferStorage(resolve_color_.id(), GL_RGBA8, width, height);
    resolve_fbo_ = GlFramebuffer::create();
    glNamedFramebufferRenderbuffer(resolve_fbo_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_color_.id());

    if (glCheckNamedFramebufferStatus(msaa_fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE ||
        glCheckNamedFramebufferStatus(resolve_fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError("cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                           " framebuffer (out of memory?)");
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, msaa_fbo_.id());
    glViewport(0, 0, width_, height_);
}

void Framebuffer::bind_resolved() const {
    glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_.id());
    glViewport(0, 0, width_, height_);
}

void Framebuffer::resolve() const {
    glBlitNamedFramebuffer(msaa_fbo_.id(), resolve_fbo_.id(), 0, 0, width_, height_, 0, 0, width_, height_,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

Image Framebuffer::read(bool unpremultiply) const {
    Image image(width_, height_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    flip_vertically(image);  // GL's first row is the bottom one; images are stored top row first
    if (unpremultiply) {
        for (size_t i = 0; i < image.rgba.size(); i += 4) {
            unsigned a = image.rgba[i + 3];
            if (a == 0 || a == 255) continue;
            for (int c = 0; c < 3; ++c)
                image.rgba[i + c] = uint8_t(std::min(255u, (image.rgba[i + c] * 255u + a / 2) / a));
        }
    }
    return image;
}

}  // namespace inkshade::gpu
