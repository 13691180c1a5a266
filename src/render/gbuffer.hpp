// The G-buffer of the image-space line passes (edges, suggestive-image): single-sample targets
// drawn by a geometry pass of their own (render/gbuffer_pass.cpp), only when one of them is on.
// (Writing them as extra render targets of the 4x MSAA shading pass cost twice as much on
// llvmpipe: every target is written per sample.) shaders/lines/gbuffer.frag writes
//   surface (RGBA32F): n.v, linear depth, object id bits, packHalf2x16(view-space w.xy)
//   face normal (RGBA8_SNORM): view-space face normal (only when `edges` looks for creases)
#pragma once
#include <epoxy/gl.h>

#include "gpu/gl_handle.hpp"

namespace inkshade::render {

class GBuffer {
public:
    GBuffer(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    // Binds the framebuffer for drawing into the surface target and, with `face_normals`, the
    // face-normal one, and clears them (background: id 0) and the depth buffer. The caller sets
    // the viewport.
    void bind_for_drawing(bool face_normals) const;
    // Binds the textures for reading (sampler2D, texelFetch).
    void bind_textures(GLuint surface_unit, GLuint face_normal_unit) const;

private:
    int width_, height_;
    gpu::GlTexture surface_, face_normal_;
    gpu::GlRenderbuffer depth_;
    gpu::GlFramebuffer fbo_;
};

}  // namespace inkshade::render
