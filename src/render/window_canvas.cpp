#include "inkshade/window_canvas.hpp"

#include <epoxy/gl.h>

#include "gpu/gl_handle.hpp"

namespace inkshade {

struct WindowCanvas::Impl {
    gpu::GlTexture texture;
    int width = 0, height = 0;
};

WindowCanvas::WindowCanvas() : impl_(std::make_unique<Impl>()) {}

WindowCanvas::~WindowCanvas() = default;

void WindowCanvas::show(const Image& image) {
    if (image.width <= 0 || image.height <= 0) return;  // GL has no texture of no pixels
    if (!impl_->texture || image.width != impl_->width || image.height != impl_->height) {
        // Immutable storage of the image's size: a new texture when the window is resized.
        impl_->texture = gpu::GlTexture::create(GL_TEXTURE_2D);
        glTextureStorage2D(impl_->texture.id(), 1, GL_RGBA8, image.width, image.height);
        glTextureParameteri(impl_->texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(impl_->texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        impl_->width = image.width;
        impl_->height = image.height;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(impl_->texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.rgba.data());
}

std::uintptr_t WindowCanvas::texture_id() const { return impl_->texture.id(); }

void WindowCanvas::clear_window(int width, int height, const glm::vec4& color) const {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(color.r, color.g, color.b, color.a);
    glClear(GL_COLOR_BUFFER_BIT);
}

Image WindowCanvas::read_window(int width, int height) const {
    Image image(width, height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    flip_vertically(image);
    return image;
}

}  // namespace inkshade
