#include "render/surface_lines.hpp"

#include "gpu/embedded_shaders.hpp"

namespace inkshade::render {

std::string SurfaceLines::defines() const {
    if (!active()) return "";
    const bool compensate = line_param(*rim, "compensate").at(0) != 0.0f;
    return "#define main inkshade_shading_main\n"
           "#define INKSHADE_RIM_COMPENSATE " + std::to_string(compensate ? 1 : 0) + "\n";
}

std::string SurfaceLines::epilogue(const std::string& fragment_path) const {
    if (!active()) return "";
    // Models built on common/surface.glsl declare the interpolated position and normal
    // already; the others (gouraud) get them from here.
    const bool declared = gpu::shader_source(fragment_path).find("in vec3 v_world_normal;") != std::string::npos;
    return std::string(declared ? "#define INKSHADE_SURFACE_INPUTS 1\n" : "") +
           gpu::shader_source("lines/surface_lines.glsl");
}

void SurfaceLines::upload(gpu::ShaderProgram& program) const {
    if (!rim) return;
    const Stroke s = stroke_of(*rim);
    program.set("u_rim_contour_threshold", line_param(*rim, "threshold").at(0));
    program.set("u_rim_contour_color", s.color);
    program.set("u_rim_contour_opacity", s.opacity);
    program.set("u_rim_contour_width", s.width);
}

}  // namespace inkshade::render
