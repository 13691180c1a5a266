#include "render/shadow_pass.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "inkshade/error.hpp"

namespace inkshade::render {

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

ShadowPass::ShadowPass(int size) : size_(size) {
    glCreateTextures(GL_TEXTURE_2D, 1, &depth_);
    glTextureStorage2D(depth_, 1, GL_DEPTH_COMPONENT32F, size, size);
    glTextureParameteri(depth_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(depth_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(depth_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(depth_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(depth_, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(depth_, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glCreateFramebuffers(1, &fbo_);
    glNamedFramebufferTexture(fbo_, GL_DEPTH_ATTACHMENT, depth_, 0);
    glNamedFramebufferDrawBuffer(fbo_, GL_NONE);
    glNamedFramebufferReadBuffer(fbo_, GL_NONE);
    if (glCheckNamedFramebufferStatus(fbo_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError("cannot create the shadow-map framebuffer");
    program_ = std::make_unique<gpu::ShaderProgram>("shadow/depth.vert", "shadow/depth.frag");
}

ShadowPass::~ShadowPass() {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteTextures(1, &depth_);
}

void ShadowPass::render(const GpuMesh& mesh, const glm::mat4& light_view_proj, bool closed) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, size_, size_);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    if (closed) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
    } else {
        glDisable(GL_CULL_FACE);  // open meshes cast shadows from both sides
    }
    // Slope-scaled depth bias against self-shadowing acne (with the lookup's normal offset).
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);
    program_->use();
    program_->set("u_model", glm::mat4(1.0f));
    program_->set("u_light_view_proj", light_view_proj);
    mesh.draw();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glCullFace(GL_BACK);
}

void ShadowPass::bind(GLuint unit) const { glBindTextureUnit(unit, depth_); }

}  // namespace inkshade::render
