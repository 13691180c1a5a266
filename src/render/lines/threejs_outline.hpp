// `threejs-outline`: three.js's OutlineEffect, the outline three.js toon scenes draw: back faces
// pushed out by `thickness` in normalised device coordinates (shaders/lines/threejs_outline.vert),
// drawn after the model in the sRGB-encoded outline colour (docs/threejs.md).
#pragma once
#include <memory>

#include "gpu/shader_program.hpp"
#include "inkshade/camera.hpp"
#include "inkshade/lines.hpp"
#include "render/gpu_mesh.hpp"

namespace inkshade::render {

class ThreejsOutlinePass {
public:
    ThreejsOutlinePass();
    // Draws into the bound framebuffer (depth-tested against the shaded model).
    void draw(const GpuMesh& mesh, const Camera& camera, int width, int height, const LineSettings& settings);

private:
    std::unique_ptr<gpu::ShaderProgram> program_;
};

}  // namespace inkshade::render
