// The mesh's back faces drawn as a line shell around the shaded model, pushed out by the bound
// program's vertex stage: the inverted hull (render/lines/hull.cpp) and three.js's
// OutlineEffect (render/lines/threejs_outline.cpp).
#pragma once
#include <epoxy/gl.h>

#include "gpu/shader_program.hpp"
#include "render/frame.hpp"

namespace inkshade::render {

// Draws the frame's mesh's back faces (front faces culled) with `program`, bound, depth-tested
// with `depth_func` (GL_LESS, GL_LEQUAL) and pushed back in depth as the shading pass pushed
// its back faces (render/back_faces.hpp), so the shell relates to the model's back faces as
// without the push: opaque without depth writes (a line, not a surface that should hide later
// lines; fewer per-sample writes), or, with `blend`, premultiplied "over" (the framebuffer holds
// premultiplied colour) with depth writes so overlapping layers of the shell blend once. The GL
// state is as before afterwards.
void draw_back_face_shell(const Frame& frame, gpu::ShaderProgram& program, GLenum depth_func, bool blend);

}  // namespace inkshade::render
