// `rim-contour`: the fragment test |n.v| < threshold inside the shading pass
// (shaders/lines/surface_lines.glsl; uniforms set by render/surface_lines.cpp).
#include "inkshade/lines.hpp"

namespace inkshade::render {
namespace {

std::vector<ParamSpec> rim_params() {
    std::vector<ParamSpec> p = stroke_params(glm::vec3(0.0f), 2.0f);
    p.push_back(float_param("threshold", 0.175f, 0.0f, 1.0f,
                            "band |n.v| < threshold (Qu et al. 2022's contour tolerance, 0.175)"));
    p.push_back(compile_time(bool_param("compensate", false,
                                        "width compensation by curvature: band = pixels within width px of the "
                                        "contour, distance |n.v| / (2 |grad n.v|)")));
    return p;
}

const LineTypeRegistration rim_contour_type{{
    .name = "rim-contour",
    .summary = "fragment test |n.v| < threshold, anti-aliased, optional constant pixel width",
    .space = LineSpace::Image,
    .params = rim_params(),
}};

}  // namespace
}  // namespace inkshade::render
