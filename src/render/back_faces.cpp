#include "render/back_faces.hpp"

#include <algorithm>
#include <cmath>

namespace inkshade::render {

namespace {

// Slope-scaled part of the tolerance: one pixel of the back face's own depth slope.
constexpr float kSlopeFactor = 1.0f;

// The frame's push: none when back faces are culled (nothing to compare them with).
float frame_push(const Frame& frame) {
    return frame.cull_back_faces ? 0.0f : back_face_depth_push(frame.camera, frame.aspect(), frame.options.height);
}

}  // namespace

float back_face_depth_push(const Camera& camera, float aspect, int height) {
    const glm::mat4 p = camera.projection(aspect);
    const float h = float(std::max(height, 1));
    if (camera.orthographic) {
        // z_clip = p[2][2] z_view + p[3][2]; the point moves by -δ along view z.
        const float delta = kBackFaceTolerancePx * camera.ortho_height / h;
        return -p[2][2] * delta;
    }
    // Scaling the view-space point by s: clip (s x, s y, s c z + d, s w) ~ (x, y, c z + d / s, w),
    // so clip z gains d (1/s - 1) with d = p[3][2] (negative: the offset is positive).
    const float eps = kBackFaceTolerancePx * 2.0f * std::tan(0.5f * glm::radians(camera.fov_degrees)) / h;
    return p[3][2] * (1.0f / (1.0f + eps) - 1.0f);
}

void draw_front_then_back(const Frame& frame, gpu::ShaderProgram& program, const std::function<void()>& draw) {
    draw_front_then_back(frame, program, [&](bool) { draw(); });
}

void draw_front_then_back(const Frame& frame, gpu::ShaderProgram& program, const std::function<void(bool back)>& draw) {
    {
        const gpu::CullScope cull(GL_BACK);
        program.set("u_back_face_push", 0.0f);
        draw(false);
    }
    if (frame.cull_back_faces) return;
    const gpu::CullScope cull(GL_FRONT);
    const gpu::PolygonOffsetScope offset(kSlopeFactor, 0.0f);
    program.set("u_back_face_push", frame_push(frame));
    draw(true);
}

BackFacePushScope::BackFacePushScope(const Frame& frame, gpu::ShaderProgram& program) {
    program.set("u_back_face_push", frame_push(frame));
    if (!frame.cull_back_faces) offset_.emplace(kSlopeFactor, 0.0f);
}

}  // namespace inkshade::render
