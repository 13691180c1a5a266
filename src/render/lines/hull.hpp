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

class HullPass {
public:
    HullPass();
    // Draws into the bound framebuffer (depth-tested against the shaded model, blended).
    void draw(const GpuMesh& mesh, const Camera& camera, int width, int height, const LineSettings& settings);

private:
    std::unique_ptr<gpu::ShaderProgram> program_;
};

}  // namespace inkshade::render
