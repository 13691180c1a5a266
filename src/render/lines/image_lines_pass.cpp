#include "render/lines/image_lines_pass.hpp"

#include <algorithm>
#include <cmath>

namespace inkshade::render {

namespace {

bool on(const LineSettings& s, const char* name) { return line_param(s, name).at(0) != 0.0f; }

}  // namespace

ImageLinesPass::ImageLinesPass() { glCreateVertexArrays(1, &vao_); }

ImageLinesPass::~ImageLinesPass() { glDeleteVertexArrays(1, &vao_); }

bool ImageLinesPass::needs_face_normals(const LineSettings* edges) { return edges && on(*edges, "normal"); }

void ImageLinesPass::draw(const GBuffer& gbuffer, const Camera& camera, int width, int height,
                          const LineSettings* edges, const LineSettings* suggestive) {
    if (!edges && !suggestive) return;
    std::string defines = "#define EDGES " + std::to_string(edges ? 1 : 0) + "\n";
    defines += "#define SUGGESTIVE " + std::to_string(suggestive ? 1 : 0) + "\n";
    if (edges) {
        defines += "#define EDGES_IDS " + std::to_string(on(*edges, "ids") ? 1 : 0) + "\n";
        defines += "#define EDGES_DEPTH " + std::to_string(on(*edges, "depth") ? 1 : 0) + "\n";
        defines += "#define EDGES_NORMAL " + std::to_string(on(*edges, "normal") ? 1 : 0) + "\n";
        defines += "#define EDGES_CANNY " + std::to_string(line_param(*edges, "detector").at(0) == 1.0f ? 1 : 0) + "\n";
    }
    auto& program = programs_[defines];
    if (!program) program = std::make_unique<gpu::ShaderProgram>("lines/fullscreen.vert", "lines/image_lines.frag", defines);
    gpu::ShaderProgram& p = *program;
    p.use();
    constexpr GLuint kSurfaceUnit = 3, kFaceNormalUnit = 4;
    gbuffer.bind_textures(kSurfaceUnit, kFaceNormalUnit);
    p.set("u_gbuffer_surface", int(kSurfaceUnit));
    p.set("u_gbuffer_face_normal", int(kFaceNormalUnit));
    p.set("u_image_size", glm::ivec2(width, height));
    p.set("u_far", camera.far_plane);
    if (edges) {
        const Stroke s = stroke_of(*edges);
        p.set("u_edges_color", glm::vec4(s.color, s.opacity));
        p.set("u_edges_spacing", std::max(1, int(std::lround(0.5f * s.width))));
        p.set("u_edges_depth_threshold", line_param(*edges, "depth-threshold").at(0));
        p.set("u_edges_normal_threshold", line_param(*edges, "normal-threshold").at(0));
    }
    if (suggestive) {
        const Stroke s = stroke_of(*suggestive);
        p.set("u_sc_color", glm::vec4(s.color, s.opacity));
        p.set("u_sc_width", s.width);
        p.set("u_sc_step", int(line_param(*suggestive, "step").at(0)));
        p.set("u_sc_threshold", line_param(*suggestive, "threshold").at(0));
        p.set("u_sc_fade", line_param(*suggestive, "fade").at(0));
        p.set("u_sc_min_ndotv", line_param(*suggestive, "min-ndotv").at(0));
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over"
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_BLEND);
}

}  // namespace inkshade::render
