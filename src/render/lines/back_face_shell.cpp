#include "render/lines/back_face_shell.hpp"

#include "gpu/gl_state.hpp"
#include "render/back_faces.hpp"

namespace inkshade::render {

void draw_back_face_shell(const Frame& frame, gpu::ShaderProgram& program, GLenum depth_func, bool blend) {
    const gpu::DepthScope depth(depth_func, /*write=*/blend);
    const gpu::CullScope cull(GL_FRONT);
    const gpu::BlendScope over(blend ? std::optional<gpu::BlendFunc>(gpu::BlendFunc{
                                           GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA})
                                     : std::nullopt);
    const BackFacePushScope push(frame, program);
    frame.mesh->draw();
}

}  // namespace inkshade::render
