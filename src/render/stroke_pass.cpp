#include "render/stroke_pass.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "geometry/brush_names.hpp"
#include "geometry/line_types/object_line_registry.hpp"
#include "gpu/gl_state.hpp"
#include "render/frame.hpp"

namespace inkshade::render {

namespace {

// One segment = one instance: end points (pixels), half-widths and window depths at both ends,
// colours at both ends with, in w, whether that end is a path's flat (butt or square) cap, and
// the arc length of the path from its start at both ends (the brush runs on across joins).
struct Segment {
    glm::vec4 ends;          // x0, y0, x1, y1
    glm::vec4 radius_depth;  // r0, r1, d0, d1
    glm::vec4 color0;        // r, g, b, flat start
    glm::vec4 color1;        // r, g, b, flat end
    glm::vec2 arc;           // s0, s1
};

constexpr GLuint kAttributes = 5;

// One miter or bevel corner = one instance (shaders/lines/stroke_join.vert).
struct Join {
    glm::vec4 va;           // the vertex V, the incoming segment's outer corner A
    glm::vec4 tb;           // the miter's tip T (a bevel: the middle of A and B), the outgoing segment's B
    glm::vec4 color_depth;  // rgb, window depth at V
    glm::vec4 arc;          // arc length at V, outer side for the brush (+-1), radius at V, inner shift
};

// SVG's default stroke-miterlimit: the miter's length over the stroke's width at most 4.
constexpr float kMiterLimit = 4.0f;

// The join at vertex v between directions t1 (in) and t2 (out), radius r: none when the path
// goes straight on (or turns back on itself, where SVG draws none either).
std::optional<Join> corner_join(glm::vec2 v, glm::vec2 t1, glm::vec2 t2, float r, geometry::StrokeJoin join) {
    const float cross = t1.x * t2.y - t1.y * t2.x, dot = glm::dot(t1, t2);
    if (!(r > 0.0f) || std::abs(cross) < 1e-4f || dot < -0.9999f) return std::nullopt;
    // The outer side is away from the turn; n = (-t.y, t.x) is the side `cross` > 0 turns to.
    const float o = cross > 0.0f ? -1.0f : 1.0f;
    const glm::vec2 n1(-t1.y, t1.x), n2(-t2.y, t2.x);
    const glm::vec2 a = v + o * r * n1, b = v + o * r * n2;
    glm::vec2 tip = 0.5f * (a + b);
    const glm::vec2 m = glm::normalize(n1 + n2);
    const float c = glm::dot(m, n1);  // cos of half the turn: the miter is r / c from v
    if (join == geometry::StrokeJoin::Miter && c > 1.0f / kMiterLimit) tip = v + o * (r / c) * m;
    // The brush's `across` is 0.5 + 0.5 cross(t, p - a) / r (stroke.frag): o at the outer edge.
    return Join{glm::vec4(v, a), glm::vec4(tip, b), glm::vec4(0.0f), glm::vec4(0.0f, o, r, 0.5f * std::min(1.0f, r))};
}

// One path's capsules (a segment each, and a dot for a lone point) and, with miter and bevel
// joins, its corner polygons. Clears depth_test when the path has no depths to test.
void add_path(const LinePath& path, const StrokeStyle& style, std::vector<Segment>& segments, std::vector<Join>& joins,
              bool& depth_test) {
    const bool flat_caps = style.cap != geometry::StrokeCap::Round;
    const bool flat_joins = style.join != geometry::StrokeJoin::Round;
    const size_t n = path.points.size();
    if (n == 0) return;
    if (path.depth.size() != n) depth_test = false;
    auto radius = [&](size_t i) {
        if (path.width.size() == n) return 0.5f * std::max(path.width[i], 0.0f);
        float s = style.taper && path.strength.size() == n ? std::clamp(path.strength[i], 0.0f, 1.0f) : 1.0f;
        return 0.5f * style.width * s;
    };
    auto depth = [&](size_t i) { return path.depth.size() == n ? path.depth[i] : 0.0f; };
    auto color = [&](size_t i) { return path.color.size() == n ? path.color[i] : style.color; };
    std::vector<glm::vec2> points = path.points;
    const bool open = !path.closed && n > 1;
    if (open && style.cap == geometry::StrokeCap::Square) {
        // A square cap is a flat one half a width further out.
        auto extend = [&](size_t end, size_t inner) {
            const glm::vec2 d = points[end] - points[inner];
            const float l = glm::length(d);
            if (l > 0.0f) points[end] += d / l * radius(end);
        };
        extend(0, 1);
        extend(n - 1, n - 2);
    }
    // Cumulative image-space length from the path's start, so the brush does not restart
    // at every segment.
    // A coherent stroke's brush is read at its parameter u, so it stays on the surface.
    std::vector<float> arc(n, 0.0f);
    if (path.u.size() == n)
        arc = path.u;
    else
        for (size_t i = 1; i < n; ++i) arc[i] = arc[i - 1] + glm::length(points[i] - points[i - 1]);
    auto add = [&](size_t a, size_t b, bool flat_a, bool flat_b) {
        const glm::vec3 ca = color(a), cb = color(b);
        segments.push_back(
            {glm::vec4(points[a], points[b]), glm::vec4(radius(a), radius(b), depth(a), depth(b)),
             glm::vec4(ca, flat_a ? 1.0f : 0.0f), glm::vec4(cb, flat_b ? 1.0f : 0.0f),
             glm::vec2(arc[a], b == 0 && a != 0 ? arc[a] + glm::length(points[0] - points[a]) : arc[b])});
    };
    // Corners: with miter and bevel joins every segment ends flat at a corner (a vertex
    // with a segment on both sides) and the corner's outer side gets its polygon.
    const bool closed = path.closed && n > 2;
    auto corner = [&](size_t i) { return flat_joins && (closed || (i > 0 && i + 1 < n)); };
    if (n == 1) add(0, 0, false, false);  // a dot
    for (size_t i = 0; i + 1 < n; ++i)
        add(i, i + 1, (open && flat_caps && i == 0) || corner(i),
            (open && flat_caps && i + 2 == n) || corner(i + 1));
    if (closed) add(n - 1, 0, corner(n - 1), corner(0));
    for (size_t i = 0; flat_joins && i < n; ++i) {
        if (!corner(i)) continue;
        const glm::vec2 v = points[i], in = v - points[(i + n - 1) % n], out = points[(i + 1) % n] - v;
        if (glm::length(in) <= 0.0f || glm::length(out) <= 0.0f) continue;
        std::optional<Join> j = corner_join(v, glm::normalize(in), glm::normalize(out), radius(i), style.join);
        if (!j) continue;
        j->color_depth = glm::vec4(color(i), depth(i));
        j->arc.x = arc[i];
        joins.push_back(*j);
    }
}

}  // namespace

StrokePass::StrokePass()
    : program_("lines/stroke.vert", "lines/stroke.frag"),
      join_program_("lines/stroke_join.vert", "lines/stroke_join.frag"),
      vao_(gpu::GlVertexArray::create()),
      join_vao_(gpu::GlVertexArray::create()),
      buffer_(gpu::GlBuffer::create()),
      join_buffer_(gpu::GlBuffer::create()),
      brush_texture_(gpu::GlTexture::create(GL_TEXTURE_2D)) {
    const GLuint vao = vao_.id();
    glVertexArrayVertexBuffer(vao, 0, buffer_.id(), 0, sizeof(Segment));
    glVertexArrayBindingDivisor(vao, 0, 1);
    for (GLuint a = 0; a < kAttributes; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, a == 4 ? 2 : 4, GL_FLOAT, GL_FALSE, a * sizeof(glm::vec4));
        glVertexArrayAttribBinding(vao, a, 0);
    }
    const GLuint joins = join_vao_.id();
    glVertexArrayVertexBuffer(joins, 0, join_buffer_.id(), 0, sizeof(Join));
    glVertexArrayBindingDivisor(joins, 0, 1);
    for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexArrayAttrib(joins, a);
        glVertexArrayAttribFormat(joins, a, 4, GL_FLOAT, GL_FALSE, a * sizeof(glm::vec4));
        glVertexArrayAttribBinding(joins, a, 0);
    }
}

void StrokePass::draw(const std::vector<LinePath>& paths, const StrokeStyle& style, int width, int height,
                      int samples) {
    if (style.opacity <= 0.0f) return;
    bool depth_test = style.depth_test;
    std::vector<Segment> segments;
    std::vector<Join> joins;
    for (const LinePath& path : paths) add_path(path, style, segments, joins, depth_test);
    if (segments.empty()) return;
    glNamedBufferData(buffer_.id(), GLsizeiptr(segments.size() * sizeof(Segment)), segments.data(), GL_STREAM_DRAW);
    if (!joins.empty())
        glNamedBufferData(join_buffer_.id(), GLsizeiptr(joins.size() * sizeof(Join)), joins.data(), GL_STREAM_DRAW);

    const BrushImage* brush = style.brush;
    if (brush) upload_brush(*brush);
    auto set_uniforms = [&](gpu::ShaderProgram& p) {
        p.use();
        p.set("u_image_size", glm::vec2(width, height));
        p.set("u_color", glm::vec4(style.color, style.opacity));
        p.set("u_depth_bias", style.depth_bias);
        p.set("u_depth_test", depth_test ? 1 : 0);
        p.set("u_multisample", samples > 1 ? 1 : 0);
        p.set("u_brush", brush ? 1 : 0);
        if (brush) {
            glBindTextureUnit(0, brush_texture_.id());
            p.set("u_brush_texture", 0);
            p.set("u_brush_length",
                  style.brush_length > 0.0f ? style.brush_length : 4.0f * std::max(style.width, 0.25f));
        }
    };

    const gpu::CullScope cull(std::nullopt);
    const gpu::DepthScope depth(depth_test ? std::optional<GLenum>(GL_LEQUAL) : std::nullopt, /*write=*/false);
    std::optional<gpu::StencilScope> once_per_sample;
    if (samples > 1) {
        // Each sample once per draw: no double blending where capsules of joins overlap.
        glClear(GL_STENCIL_BUFFER_BIT);
        once_per_sample.emplace(gpu::StencilFunc{GL_EQUAL, 0, 0xff, GL_KEEP, GL_KEEP, GL_INCR});
    }
    const gpu::BlendScope blend(gpu::BlendFunc{GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA});
    set_uniforms(program_);
    glBindVertexArray(vao_.id());
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(segments.size()));
    if (joins.empty()) return;
    set_uniforms(join_program_);
    glBindVertexArray(join_vao_.id());
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(joins.size()));
}

void StrokePass::upload_brush(const BrushImage& brush) {
    // A fresh texture each draw (a brush is 1 KiB): immutable storage cannot change size.
    brush_texture_ = gpu::GlTexture::create(GL_TEXTURE_2D);
    const GLuint t = brush_texture_.id();
    const int levels = 1 + int(std::floor(std::log2(std::max(brush.width, brush.height))));
    glTextureStorage2D(t, levels, GL_R8, brush.width, brush.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(t, 0, 0, 0, brush.width, brush.height, GL_RED, GL_UNSIGNED_BYTE, brush.grey.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // Mipmaps: a brush length of a few pixels minifies the texture along the stroke.
    glGenerateTextureMipmap(t);
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void StrokePass::draw_layers(const std::vector<LineLayer>& layers, int width, int height, int samples) {
    for (const LineLayer& layer : layers) {
        const Stroke stroke = stroke_of(layer.settings);
        // Hidden parts are already cut away exactly by ray casting; a depth test would only
        // nibble at the half of a contour stroke that lies over the surface it outlines.
        const StrokeStyle style{
            .color = stroke.color,
            .opacity = stroke.opacity,
            .width = stroke.width,
            .taper = line_param(layer.settings, "taper").at(0) != 0.0f,
            .cap = geometry::stroke_ends(layer.settings).cap,
            .join = geometry::stroke_ends(layer.settings).join,
            .depth_test = false,
            .brush = shipped_brush(geometry::brush_names().at(size_t(geometry::line_number(layer.settings, "brush")))),
            .brush_length = geometry::line_number(layer.settings, "brush-length")};
        // The widths are those the SVG writer draws (geometry::drawn_widths): the paths' own,
        // else the layer's width, times the strength with taper.
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
