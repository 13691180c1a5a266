// `shadow`: the shadow map (render/shadow_map.hpp) of models that cast shadows, drawn again only
// when the mesh or the light changed.
#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "gpu/gl_state.hpp"
#include "gpu/shader_program.hpp"
#include "render/frame.hpp"

namespace inkshade::render {

namespace {

// The light's view-projection enclosing the bounding sphere of `box`: orthographic along the
// light direction for a directional light, a perspective frustum from a point light.
glm::mat4 light_view_projection(const Light& light, const BoundingBox& box) {
    const glm::vec3 center = box.center();
    const float radius = std::max(0.5f * box.diagonal(), 1e-6f);
    glm::vec3 dir = light.direction_to_light(center);  // towards the light
    glm::vec3 up = std::abs(dir.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    if (light.type == LightType::Directional) {
        glm::vec3 eye = center + dir * (2.0f * radius);
        return glm::ortho(-radius, radius, -radius, radius, radius * 0.5f, radius * 3.5f) *
               glm::lookAt(eye, center, up);
    }
    const float dist = glm::length(light.position - center);
    if (dist <= radius * 1.01f) {
        // Light inside the bounding sphere: a wide frustum towards the centre still covers most.
        return glm::perspective(glm::radians(150.0f), 1.0f, radius * 1e-3f, dist + radius) *
               glm::lookAt(light.position, center, up);
    }
    const float half_angle = std::asin(std::min(radius / dist, 0.999f));
    return glm::perspective(2.0f * half_angle * 1.05f, 1.0f, std::max(dist - radius, radius * 1e-3f), dist + radius) *
           glm::lookAt(light.position, center, up);
}

class ShadowPass final : public Pass {
public:
    ShadowPass() : program_("shadow/depth.vert", "shadow/depth.frag") {}

    // For a closed, outward mesh only the faces turned away from the light are drawn: half the
    // triangles, and the stored depth lies behind the lit surface, away from acne.
    void run(Frame& frame) override {
        FrameTargets& targets = frame.targets;
        if (!targets.shadow_map) targets.shadow_map = std::make_unique<ShadowMap>();
        const ShadowMap& map = *targets.shadow_map;
        const glm::mat4 light_view_proj = light_view_projection(frame.light, frame.bounds);
        map.bind_for_drawing();
        const gpu::ViewportScope viewport({0, 0, map.size(), map.size()});
        glClearDepth(1.0);
        glClear(GL_DEPTH_BUFFER_BIT);
        const gpu::DepthScope depth(GL_LESS);
        const gpu::CullScope cull(frame.closed ? std::optional<GLenum>(GL_FRONT)
                                               : std::nullopt);  // open meshes cast from both sides
        // Slope-scaled depth bias against self-shadowing acne (with the lookup's normal offset).
        const gpu::PolygonOffsetScope offset(2.0f, 4.0f);
        program_.use();
        program_.set("u_model", glm::mat4(1.0f));
        program_.set("u_light_view_proj", light_view_proj);
        frame.mesh->draw();
        targets.shadow_light = light_view_proj;
    }

private:
    gpu::ShaderProgram program_;
};

// Runs for the shading pass when it reads the map (PassIo), unless the map holds this light.
const PassRegistration shadow_pass{{
    .name = "shadow",
    .stage = Stage::Shadow,
    .plan = [](const Frame& frame) -> std::optional<PassIo> {
        if (frame.targets.shadow_map && frame.targets.shadow_light == light_view_projection(frame.light, frame.bounds))
            return std::nullopt;
        return PassIo{.reads = {Resource::GpuMesh}, .writes = {Resource::ShadowMap}};
    },
    .create = create_pass<ShadowPass>,
}};

}  // namespace

}  // namespace inkshade::render
