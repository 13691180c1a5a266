// Off-screen render target: multisampled colour + depth/stencil, resolved into a single-sample
// colour buffer for readback. The stencil bits let stroke layers cover each sample once
// (render/stroke_pass.hpp).
#pragma once
#include <epoxy/gl.h>

#include "gpu/gl_handle.hpp"
#include "inkshade/image.hpp"

namespace inkshade::gpu {

class Framebuffer {
public:
    // samples = 1 disables MSAA; bit_depth 8 (RGBA8) or 16 (RGBA16) bits a colour channel.
    // Throws RuntimeError when incomplete (size too large, ...).
    Framebuffer(int width, int height, int samples, int bit_depth = 8);

    int width() const { return width_; }
    int height() const { return height_; }
    int samples() const { return samples_; }
    int bit_depth() const { return bit_depth_; }
    void bind() const;
    // Resolves MSAA into the single-sample buffer (a no-op copy when samples == 1).
    void resolve() const;
    // Binds the resolved single-sample colour buffer as the draw target (passes that shade once
    // per pixel and need no depth: blending them into every sample would give the same result).
    void bind_resolved() const;
    // Reads the resolved colour, top row first; at 16 bits into the image's rgba16 as well. With
    // `unpremultiply`, colour is divided by alpha (edges antialiased against a transparent
    // background stay their own colour).
    Image read(bool unpremultiply) const;

private:
    int width_, height_, samples_, bit_depth_;
    GlRenderbuffer msaa_color_, msaa_depth_, resolve_color_;
    GlFramebuffer msaa_fbo_, resolve_fbo_;
};

}  // namespace inkshade::gpu
