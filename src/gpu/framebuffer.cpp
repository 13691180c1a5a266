#include "gpu/framebuffer.hpp"

#include <algorithm>
#include <string>

#include "inkshade/error.hpp"

namespace inkshade::gpu {

namespace {

// Divides colour by alpha, in place, for channels of `max` levels.
template <typename T>
void unpremultiply_pixels(std::vector<T>& rgba, uint64_t max) {
    for (size_t i = 0; i < rgba.size(); i += 4) {
        const uint64_t a = rgba[i + 3];
        if (a == 0 || a == max) continue;
        for (int c = 0; c < 3; ++c) rgba[i + c] = T(std::min(max, (rgba[i + c] * max + a / 2) / a));
    }
}

}  // namespace

Framebuffer::Framebuffer(int width, int height, int samples, int bit_depth)
    : width_(width), height_(height), samples_(std::max(1, samples)), bit_depth_(bit_depth == 16 ? 16 : 8) {
    GLint max_size = 0, max_samples = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    if (width <= 0 || height <= 0 || width > max_size || height > max_size)
        throw RuntimeError("image size " + std::to_string(width) + "x" + std::to_string(height) +
                           " is outside what this OpenGL supports (1.." + std::to_string(max_size) + ")");
    samples_ = std::min(samples_, std::max(1, int(max_samples)));
    const GLenum format = bit_depth_ == 16 ? GL_RGBA16 : GL_RGBA8;

    msaa_color_ = GlRenderbuffer::create();
    msaa_depth_ = GlRenderbuffer::create();
    if (samples_ > 1) {
        glNamedRenderbufferStorageMultisample(msaa_color_.id(), samples_, format, width, height);
        glNamedRenderbufferStorageMultisample(msaa_depth_.id(), samples_, GL_DEPTH32F_STENCIL8, width, height);
    } else {
        // Multisample storage with 1 sample may still be multisampled (llvmpipe rounds 1 up
        // to 4): samples = 1 must mean no MSAA, so use plain storage.
        glNamedRenderbufferStorage(msaa_color_.id(), format, width, height);
        glNamedRenderbufferStorage(msaa_depth_.id(), GL_DEPTH32F_STENCIL8, width, height);
    }
    msaa_fbo_ = GlFramebuffer::create();
    glNamedFramebufferRenderbuffer(msaa_fbo_.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaa_color_.id());
    glNamedFramebufferRenderbuffer(msaa_fbo_.id(), GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, msaa_depth_.id());

    resolve_color_ = GlRenderbuffer::create();
    glNamedRenderbufferStorage(resolve_color_.id(), format, width, height);
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
    if (bit_depth_ == 16) {
        // The 8-bit pixels are the 16-bit ones rounded, after the division by alpha.
        image.rgba16.resize(image.rgba.size());
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_SHORT, image.rgba16.data());
        if (unpremultiply) unpremultiply_pixels(image.rgba16, 65535);
        std::transform(image.rgba16.begin(), image.rgba16.end(), image.rgba.begin(), to_8_bits);
    } else {
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
        if (unpremultiply) unpremultiply_pixels(image.rgba, 255);
    }
    flip_vertically(image);  // GL's first row is the bottom one; images are stored top row first
    return image;
}

}  // namespace inkshade::gpu
