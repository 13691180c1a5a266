#include "render/lines/image_lines_pass.hpp"

#include <algorithm>
#include <cmath>

#include "gpu/gl_state.hpp"
#include "render/frame.hpp"

namespace inkshade::render {

namespace {

bool on(const LineSettings& s, const char* name) { return line_param(s, name).at(0) != 0.0f; }

}  // namespace

ImageLinesPass::ImageLinesPass() : vao_(gpu::GlVertexArray::create()) {}

glm::ivec4 ImageLinesPass::image_lines_region(const BoundingBox& bounds, const Camera& camera, int width, int height,
                                              int margin) {
    const glm::ivec4 whole(0, 0, width, height);
    const glm::mat4 clip_from_world = camera.projection(float(width) / float(height)) * camera.view();
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                               (i & 4) ? bounds.max.z : bounds.min.z);
        const glm::vec4 c = clip_from_world * glm::vec4(corner, 1.0f);
        // w > 0 at every corner: w is affine, so the whole box is in front of the eye and its
        // projection is the hull of the corners' projections.
        if (!(c.w > 1e-6f)) return whole;
        const glm::vec2 ndc = glm::vec2(c) / c.w;
        lo = glm::min(lo, ndc), hi = glm::max(hi, ndc);
    }
    if (!std::isfinite(lo.x) || !std::isfinite(lo.y) || !std::isfinite(hi.x) || !std::isfinite(hi.y)) return whole;
    // NDC to window pixels (glViewport), grown by the margin and a pixel for rounding.
    const auto to_px = [](float ndc, int size) { return double(ndc + 1.0f) * 0.5 * size; };
    const double x0 = std::floor(to_px(lo.x, width)) - margin - 1, x1 = std::ceil(to_px(hi.x, width)) + margin + 1;
    const double y0 = std::floor(to_px(lo.y, height)) - margin - 1, y1 = std::ceil(to_px(hi.y, height)) + margin + 1;
    const int ax = int(std::clamp(x0, 0.0, double(width))), bx = int(std::clamp(x1, 0.0, double(width)));
    const int ay = int(std::clamp(y0, 0.0, double(height))), by = int(std::clamp(y1, 0.0, double(height)));
    return {ax, ay, bx - ax, by - ay};
}

void ImageLinesPass::run(Frame& frame) {
    const LineSettings* edges = frame.line("edges");
    const LineSettings* suggestive = frame.line("suggestive-image");
    const Camera& camera = frame.camera;
    const int width = frame.options.width, height = frame.options.height;
    // Pixels farther than this from the object's footprint see only background in all their
    // taps: suggestive-image draws on the surface only; edges reach one spacing for ids and
    // depth, two with Canny's non-maximum suppression.
    const int edge_spacing = edges ? std::max(1, int(std::lround(0.5f * stroke_of(*edges).width))) : 0;
    const int margin = std::max(2, 2 * edge_spacing + 2);
    const glm::ivec4 region = image_lines_region(frame.bounds, camera, width, height, margin);
    if (region.z <= 0 || region.w <= 0) return;
    std::string defines = "#define EDGES " + std::to_string(edges ? 1 : 0) + "\n";
    defines += "#define SUGGESTIVE " + std::to_string(suggestive ? 1 : 0) + "\n";
    if (edges) {
        defines += "#define EDGES_IDS " + std::to_string(on(*edges, "ids") ? 1 : 0) + "\n";
        defines += "#define EDGES_DEPTH " + std::to_string(on(*edges, "depth") ? 1 : 0) + "\n";
        defines += "#define EDGES_NORMAL " + std::to_string(on(*edges, "normal") ? 1 : 0) + "\n";
        defines += "#define EDGES_CANNY " + std::to_string(line_param(*edges, "detector").at(0) == 1.0f ? 1 : 0) + "\n";
    }
    auto& program = programs_[defines];
    if (!program)
        program = std::make_unique<gpu::ShaderProgram>("lines/fullscreen.vert", "lines/image_lines.frag", defines);
    gpu::ShaderProgram& p = *program;
    p.use();
    constexpr GLuint kSurfaceUnit = 3, kFaceNormalUnit = 4;
    frame.targets.gbuffer->bind_textures(kSurfaceUnit, kFaceNormalUnit);
    p.set("u_gbuffer_surface", int(kSurfaceUnit));
    p.set("u_gbuffer_face_normal", int(kFaceNormalUnit));
    p.set("u_image_size", glm::ivec2(width, height));
    p.set("u_far", camera.far_plane);
    if (edges) {
        const Stroke s = stroke_of(*edges);
        p.set("u_edges_color", glm::vec4(s.color, s.opacity));
        p.set("u_edges_spacing", edge_spacing);
        p.set("u_edges_depth_threshold", line_param(*edges, "depth-threshold").at(0));
        p.set("u_edges_normal_threshold", line_param(*edges, "normal-threshold").at(0));
    }
    if (suggestive) {
        const Stroke s = stroke_of(*suggestive);
        p.set("u_sc_color", glm::vec4(s.color, s.opacity));
        p.set("u_sc_width", s.width);
        p.set("u_sc_step", int(line_param(*suggestive, "step").at(0)));
        p.set("u_sc_span_world", line_param(*suggestive, "edge-span").at(0) * frame.edge_length);
        // A pixel's world size at linear depth z (its footprint).
        const float per_height = 1.0f / float(height);
        p.set("u_sc_footprint",
              camera.orthographic
                  ? glm::vec2(camera.ortho_height * per_height, 0.0f)
                  : glm::vec2(0.0f, 2.0f * std::tan(0.5f * glm::radians(camera.fov_degrees)) * per_height));
        p.set("u_sc_threshold", line_param(*suggestive, "threshold").at(0));
        p.set("u_sc_fade", line_param(*suggestive, "fade").at(0));
        p.set("u_sc_min_ndotv", line_param(*suggestive, "min-ndotv").at(0));
    }
    const gpu::DepthScope depth(std::nullopt);
    const gpu::CullScope cull(std::nullopt);
    const gpu::BlendScope blend(
        gpu::BlendFunc{GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA});  // premultiplied "over"
    const gpu::ScissorScope scissor(region);
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

namespace {

// Runs when the style has `edges` or `suggestive-image`; reads the face normals when `edges`
// looks for creases.
const PassRegistration image_lines_pass{{
    .name = "image-lines",
    .stage = Stage::ImageLines,
    .plan = [](const Frame& frame) -> std::optional<PassIo> {
        const LineSettings* edges = frame.line("edges");
        if (!edges && !frame.line("suggestive-image")) return std::nullopt;
        PassIo io{.reads = {Resource::GBuffer}, .writes = {Resource::Color}};
        if (edges && on(*edges, "normal")) io.reads |= {Resource::GBufferFaceNormals};
        return io;
    },
    .per_pixel = true,
    .create = create_pass<ImageLinesPass>,
}};

}  // namespace

}  // namespace inkshade::render
