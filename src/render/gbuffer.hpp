// The G-buffer of the image-space line passes (edges, suggestive-image): a single-sample
// geometry pass of its own, drawn only when one of them is on. (Writing it as extra render
// targets of the 4x MSAA shading pass cost twice as much on llvmpipe: every target is
// written per sample.) shaders/lines/gbuffer.frag writes
//   surface (RGBA32F): n.v, linear depth, object id bits, packHalf2x16(view-space w.xy)
//   face normal (RGBA8_SNORM): view-space face normal (only when `edges` looks for creases)
#pragma once
#include <memory>

#include <epoxy/gl.h>

#include "gpu/shader_program.hpp"
#include "inkshade/camera.hpp"
#include "render/gpu_mesh.hpp"

namespace inkshade::render {

class GBuffer {
public:
    GBuffer(int width, int height);
    ~GBuffer();
    GBuffer(const GBuffer&) = delete;
    GBuffer& operator=(const GBuffer&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    // Draws `mesh` seen by `camera` into the G-buffer (background: id 0). `cull_back_faces` as
    // for the shading pass (closed meshes seen from outside).
    void draw(const GpuMesh& mesh, const Camera& camera, bool face_normals, bool cull_back_faces);
    // Binds the textures for reading (sampler2D, texelFetch).
    void bind_textures(GLuint surface_unit, GLuint face_normal_unit) const;

private:
    int width_, height_;
    GLuint fbo_ = 0, surface_ = 0, face_normal_ = 0, depth_ = 0;
    std::unique_ptr<gpu::ShaderProgram> programs_[2];  // without / with face normals
};

}  // namespace inkshade::render
