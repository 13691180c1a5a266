#include "render/stroke_pass.hpp"

#include <algorithm>

namespace inkshade::render {

namespace {

// One segment = one instance: end points (pixels), half-widths and window depths at both ends.
struct Segment {
    glm::vec4 ends;    // x0, y0, x1, y1
    glm::vec4 radius_depth;  // r0, r1, d0, d1
};

}  // namespace

StrokePass::StrokePass()
    : program_(std::make_unique<gpu::ShaderProgram>("lines/stroke.vert", "lines/stroke.frag")) {
    glCreateVertexArrays(1, &vao_);
    glCreateBuffers(1, &buffer_);
    glVertexArrayVertexBuffer(vao_, 0, buffer_, 0, sizeof(Segment));
    glVertexArrayBindingDivisor(vao_, 0, 1);
    for (GLuint a = 0; a < 2; ++a) {
        glEnableVertexArrayAttrib(vao_, a);
        glVertexArrayAttribFormat(vao_, a, 4, GL_FLOAT, GL_FALSE, a * sizeof(glm::vec4));
        glVertexArrayAttribBinding(vao_, a, 0);
    }
}

StrokePass::~StrokePass() {
    glDeleteVertexArrays(1, &vao_);
    glDeleteBuffers(1, &buffer_);
}

void StrokePass::draw(const std::vector<LinePath>& paths, const StrokeStyle& style, int width, int height,
                      int samples) {
    if (style.opacity <= 0.0f || style.width <= 0.0f) return;
    bool depth_test = true;
    std::vector<Segment> segments;
    for (const LinePath& path : paths) {
        const size_t n = path.points.size();
        if (n == 0) continue;
        if (path.depth.size() != n) depth_test = false;
        auto radius = [&](size_t i) {
            float s = style.taper && path.strength.size() == n ? std::clamp(path.strength[i], 0.0f, 1.0f) : 1.0f;
            return 0.5f * style.width * s;
        };
        auto depth = [&](size_t i) { return path.depth.size() == n ? path.depth[i] : 0.0f; };
        auto add = [&](size_t a, size_t b) {
            segments.push_back({glm::vec4(path.points[a], path.points[b]),
                                glm::vec4(radius(a), radius(b), depth(a), depth(b))});
        };
        if (n == 1) add(0, 0);  // a dot
        for (size_t i = 0; i + 1 < n; ++i) add(i, i + 1);
        if (path.closed && n > 2) add(n - 1, 0);
    }
    if (segments.empty()) return;
    glNamedBufferData(buffer_, GLsizeiptr(segments.size() * sizeof(Segment)), segments.data(), GL_STREAM_DRAW);

    gpu::ShaderProgram& p = *program_;
    p.use();
    p.set("u_image_size", glm::vec2(width, height));
    p.set("u_color", glm::vec4(style.color, style.opacity));
    p.set("u_depth_bias", style.depth_bias);
    p.set("u_depth_test", depth_test ? 1 : 0);
    p.set("u_multisample", samples > 1 ? 1 : 0);

    glDisable(GL_CULL_FACE);
    if (depth_test) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    glDepthMask(GL_FALSE);
    if (samples > 1) {
        // Each sample once per draw: no double blending where capsules of joins overlap.
        glClear(GL_STENCIL_BUFFER_BIT);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_EQUAL, 0, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    }
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glBindVertexArray(vao_);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(segments.size()));
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

}  // namespace inkshade::render
