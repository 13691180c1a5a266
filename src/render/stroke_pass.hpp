// Anti-aliased strokes for polylines given in image pixels (inkshade/line_drawing.hpp's
// LinePath: origin top-left, y down): every segment is a quad around a capsule (round joins, so
// no gaps at any angle; round caps, or flat ones cut square at a path's ends for butt and square
// caps; for miter and bevel joins the segments end flat at the corners and each corner's outer
// side is filled by a polygon, SVG's stroke-linejoin), width per point (LinePath::width from the layer's stroke
// modifiers, else the style's, optionally tapered by per-point strength) and colour per point (LinePath::color); the
// fragment shader computes coverage analytically. With MSAA each sample is tested against the
// capsule (gl_SampleMask) and the stencil lets a sample be covered once per draw, so joins and
// overlaps of one layer never blend twice; without MSAA the pixel coverage becomes alpha.
// Depth-tested against the scene with a bias when every path has per-point depth and the style
// asks for it. As the `strokes` pass it draws the frame's object-space lines (LineDrawing); the
// renderer's Renderer::draw_lines draws a line drawing alone with the same code.
#pragma once
#include <vector>

#include "gpu/gl_handle.hpp"
#include "geometry/stroke_style.hpp"
#include "gpu/shader_program.hpp"
#include "render/brush_texture.hpp"
#include "inkshade/line_drawing.hpp"
#include "render/pass.hpp"

namespace inkshade::render {

struct StrokeStyle {
    glm::vec3 color{0.0f};
    float opacity = 1.0f;
    float width = 1.0f;  // pixels; times strength when taper is on (LinePath::width replaces both)
    bool taper = true;   // width * strength (LinePath::strength) per point
    geometry::StrokeCap cap = geometry::StrokeCap::Round;  // at the ends of open paths
    // At a path's corners: round (the capsules' ends), or miter (up to SVG's miter limit 4,
    // then bevel) and bevel, where the segments end flat and a polygon fills the outer side.
    geometry::StrokeJoin join = geometry::StrokeJoin::Round;
    float depth_bias = 2e-4f;           // subtracted from the paths' window depth before the test
    bool depth_test = true;             // false: no test even where the paths carry depth
    const BrushImage* brush = nullptr;  // null: solid; else its texture times the coverage (outlives the draw)
    float brush_length = 0.0f;          // pixels of arc length per repeat of the brush; 0: 4 × width
};

class StrokePass final : public Pass {
public:
    StrokePass();

    // Draws `paths` into the bound framebuffer of width x height pixels with `samples`
    // samples (its depth/stencil buffer is used; the stencil is cleared).
    void draw(const std::vector<LinePath>& paths, const StrokeStyle& style, int width, int height, int samples);
    // Draws the visible parts of `layers` (hidden ones are SVG-only) with their strokes, without
    // a depth test: ray casting has already cut the hidden parts away exactly.
    void draw_layers(const std::vector<LineLayer>& layers, int width, int height, int samples);
    // Draws every layer of the frame's LineDrawing (draw_layers).
    void run(Frame& frame) override;

private:
    void upload_brush(const BrushImage& brush);

    gpu::ShaderProgram program_, join_program_;
    gpu::GlVertexArray vao_, join_vao_;
    gpu::GlBuffer buffer_, join_buffer_;
    gpu::GlTexture brush_texture_;
};

}  // namespace inkshade::render
