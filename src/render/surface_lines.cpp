#include "render/surface_lines.hpp"

namespace inkshade::render {

std::string SurfaceLines::defines() const {
    if (!active()) return "";
    const bool compensate = line_param(*rim, "compensate").at(0) != 0.0f;
    return "#define INKSHADE_RIM_CONTOUR 1\n"
           "#define INKSHADE_RIM_COMPENSATE " +
           std::to_string(compensate ? 1 : 0) + "\n";
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
