// What a front end with its own window (the viewer) shows: the renderer's image as a texture of
// the window's OpenGL context, for the window's GUI to draw, and the window's framebuffer
// cleared and read back. The front end itself then makes no OpenGL call: GL is render's and
// gpu's alone (docs/architecture.md).
#pragma once
#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

#include "inkshade/image.hpp"

namespace inkshade {

class WindowCanvas {
public:
    // Every call, construction and destruction included, wants the window's OpenGL 4.5 context
    // current (the one a Renderer(make_current) draws with).
    WindowCanvas();
    ~WindowCanvas();
    WindowCanvas(const WindowCanvas&) = delete;
    WindowCanvas& operator=(const WindowCanvas&) = delete;

    // The texture's pixels become the image's (8 bits a channel, top row at v = 0), its size the
    // image's; filtered nearest, so a window of the image's size shows it pixel for pixel.
    void show(const Image& image);
    // The texture's OpenGL name, the handle Dear ImGui's OpenGL 3 back end takes (ImTextureID).
    std::uintptr_t texture_id() const;

    // Binds the window's own framebuffer, `width` x `height` pixels, and clears all of it to
    // `color`: what the GUI then draws over.
    void clear_window(int width, int height, const glm::vec4& color) const;
    // The window's back buffer, what the next swap shows, top row first.
    Image read_window(int width, int height) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace inkshade
