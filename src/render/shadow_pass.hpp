// Shadow map: depth of the mesh from the light, for models that cast shadows (mtoon).
#pragma once
#include <epoxy/gl.h>

#include <memory>

#include "gpu/shader_program.hpp"
#include "inkshade/camera.hpp"
#include "render/gpu_mesh.hpp"

namespace inkshade::render {

// The light's view-projection enclosing the bounding sphere of `box`: orthographic along the
// light direction for a directional light, a perspective frustum from a point light.
glm::mat4 light_view_projection(const Light& light, const BoundingBox& box);

class ShadowPass {
public:
    explicit ShadowPass(int size = 2048);
    ~ShadowPass();
    ShadowPass(const ShadowPass&) = delete;
    ShadowPass& operator=(const ShadowPass&) = delete;

    // Renders the depth map; leaves the shadow framebuffer bound (caller rebinds its own).
    // For a closed, outward mesh only the faces turned away from the light are drawn: half
    // the triangles, and the stored depth lies behind the lit surface, away from acne.
    void render(const GpuMesh& mesh, const glm::mat4& light_view_proj, bool closed);
    // Binds the depth texture (comparison sampler) to texture `unit`.
    void bind(GLuint unit) const;
    int size() const { return size_; }

private:
    int size_;
    GLuint fbo_ = 0, depth_ = 0;
    std::unique_ptr<gpu::ShaderProgram> program_;
};

}  // namespace inkshade::render
