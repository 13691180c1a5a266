// The mesh's back faces drawn as a line shell around the shaded model, pushed out by the bound
// program's vertex stage: the inverted hull (render/lines/hull.cpp) and three.js's
// OutlineEffect (render/lines/threejs_outline.cpp).
#pragma once
#include <epoxy/gl.h>

#include "render/gpu_mesh.hpp"

namespace inkshade::render {

// Draws the mesh's back faces (front faces culled) with the bound program, depth-tested with
// `depth_func` (GL_LESS, GL_LEQUAL): opaque without depth writes (a line, not a surface that
// should hide later lines; fewer per-sample writes), or, with `blend`, premultiplied "over"
// (the framebuffer holds premultiplied colour) with depth writes so overlapping layers of the
// shell blend once. The GL state is as before afterwards.
void draw_back_face_shell(const GpuMesh& mesh, GLenum depth_func, bool blend);

}  // namespace inkshade::render
