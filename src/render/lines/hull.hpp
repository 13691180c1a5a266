// `hull`: the inverted hull silhouette (seeds 000 section 3.6 and 001): a copy of the mesh
// pushed out along its welded normals, front faces culled, drawn in the line colour after the
// shaded model so only the rim around it (and around parts in front of others) stays visible.
#pragma once
#include <memory>

#include "gpu/shader_program.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/lines.hpp"
#include "render/gpu_mesh.hpp"

namespace inkshade::render {

// Draws the mesh's back faces (front faces culled) with the bound program as a line shell
// around the shaded model, depth-tested with `depth_func` (GL_LESS, GL_LEQUAL): opaque without
// depth writes (a line, not a surface that should hide later lines; fewer per-sample writes),
// or, with `blend`, premultiplied "over" (the framebuffer holds premultiplied colour) with
// depth writes so overlapping layers of the shell blend once. Restores the default state.
void draw_back_face_shell(const GpuMesh& mesh, GLenum depth_func, bool blend);

class HullPass {
public:
    HullPass();
    // Draws into the bound framebuffer (depth-tested against the shaded model, blended).
    void draw(const GpuMesh& mesh, const Camera& camera, int width, int height, const LineSettings& settings);

private:
    std::unique_ptr<gpu::ShaderProgram> program_;
};

}  // namespace inkshade::render
