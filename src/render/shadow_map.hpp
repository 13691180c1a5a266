// The shadow map: depth of the mesh from the light (a depth texture with comparison sampling,
// and its framebuffer), for models that cast shadows (mtoon). Drawn by the shadow pass
// (render/shadow_pass.cpp), read by the shading pass.
#pragma once
#include <epoxy/gl.h>

#include "gpu/gl_handle.hpp"

namespace inkshade::render {

class ShadowMap {
public:
    explicit ShadowMap(int size = 2048);

    int size() const { return size_; }
    // Binds its framebuffer for drawing (the caller sets the viewport).
    void bind_for_drawing() const { glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id()); }
    // Binds the depth texture (comparison sampler) to texture `unit`.
    void bind(GLuint unit) const { glBindTextureUnit(unit, depth_.id()); }

private:
    int size_;
    gpu::GlTexture depth_;
    gpu::GlFramebuffer fbo_;
};

}  // namespace inkshade::render
