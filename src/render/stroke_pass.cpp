#include "render/stroke_pass.hpp"

#include <algorithm>

#include "gpu/gl_state.hpp"
#include "render/frame.hpp"

namespace inkshade::render {

namespace {

// One segment = one instance: end points (pixels), half-widths and window depths at both ends.
struct Segment {
    glm::vec4 ends;          // x0, y0, x1, y1
    glm::vec4 radius_depth;  // r0, r1, d0, d1
};

}  // namespace

StrokePass::StrokePass()
    : program_("lines/stroke.vert", "lines/stroke.frag"),
      vao_(gpu::GlVertexArray::create()),
      buffer_(gpu::GlBuffer::create()) {
    const GLuint vao = vao_.id();
    glVertexArrayVertexBuffer(vao, 0, buffer_.id(), 0, sizeof(Segment));
    glVertexArrayBindingDivisor(vao, 0, 1);
    for (GLuint a = 0; a < 2; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, 4, GL_FLOAT, GL_FALSE, a * sizeof(glm::vec4));
        glVertexArrayAttribBinding(vao, a, 0);
    }
}

void StrokePass::draw(const std::vector<LinePath>& paths, const StrokeStyle& style, int width, int height,
                      int samples) {
    if (style.opacity <= 0.0f || style.width <= 0.0f) return;
    bool depth_test = style.depth_test;
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
            segments.push_back(
                {glm::vec4(path.points[a], path.points[b]), glm::vec4(radius(a), radius(b), depth(a), depth(b))});
        };
        if (n == 1) add(0, 0);  // a dot
        for (size_t i = 0; i + 1 < n; ++i) add(i, i + 1);
        if (path.closed && n > 2) add(n - 1, 0);
    }
    if (segments.empty()) return;
    glNamedBufferData(buffer_.id(), GLsizeiptr(segments.size() * sizeof(Segment)), segments.data(), GL_STREAM_DRAW);

    gpu::ShaderProgram& p = program_;
    p.use();
    p.set("u_image_size", glm::vec2(width, height));
    p.set("u_color", glm::vec4(style.color, style.opacity));
    p.set("u_depth_bias", style.depth_bias);
    p.set("u_depth_test", depth_test ? 1 : 0);
    p.set("u_multisample", samples > 1 ? 1 : 0);

    const gpu::CullScope cull(std::nullopt);
    const gpu::DepthScope depth(depth_test ? std::optional<GLenum>(GL_LEQUAL) : std::nullopt, /*write=*/false);
    std::optional<gpu::StencilScope> once_per_sample;
    if (samples > 1) {
        // Each sample once per draw: no double blending where capsules of joins overlap.
        glClear(GL_STENCIL_BUFFER_BIT);
        once_per_sample.emplace(gpu::StencilFunc{GL_EQUAL, 0, 0xff, GL_KEEP, GL_KEEP, GL_INCR});
    }
    const gpu::BlendScope blend(gpu::BlendFunc{GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA});
    glBindVertexArray(vao_.id());
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(segments.size()));
}

void StrokePass::draw_layers(const std::vector<LineLayer>& layers, int width, int height, int samples) {
    for (const LineLayer& layer : layers) {
        const Stroke stroke = stroke_of(layer.settings);
        // Hidden parts are already cut away exactly by ray casting; a depth test would only
        // nibble at the half of a contour stroke that lies over the surface it outlines.
        const StrokeStyle style{.color = stroke.color,
                                .opacity = stroke.opacity,
                                .width = stroke.width,
                                .taper = line_param(layer.settings, "taper").at(0) != 0.0f,
                                .depth_test = false};
        draw(layer.visible, style, width, height, samples);
    }
}

void StrokePass::run(Frame& frame) {
    draw_layers(frame.drawing->layers, frame.options.width, frame.options.height, frame.options.samples);
}

namespace {

// Runs when the style has object-space lines.
const PassRegistration strokes_pass{{
    .name = "strokes",
    .stage = Stage::Strokes,
    .plan = [](const Frame& frame) -> std::optional<PassIo> {
        if (frame.object_lines.empty()) return std::nullopt;
        return PassIo{.reads = {Resource::LineDrawing, Resource::Color}, .writes = {Resource::Color}};
    },
    .create = create_pass<StrokePass>,
}};

}  // namespace

}  // namespace inkshade::render
