// `edges`: image-space discontinuities of the G-buffer (depth, face normal, object id), the
// approach of Saito & Takahashi 1990, "Comprehensible Rendering of 3-D Shapes"; drawn by
// ImageLinesPass (shaders/lines/edges.glsl).
#include "inkshade/lines.hpp"

namespace inkshade::render {
namespace {

std::vector<ParamSpec> edges_params() {
    std::vector<ParamSpec> p = stroke_params(glm::vec3(0.0f), 2.0f);
    p.push_back(compile_time(
        choice_param("detector", {"sobel", "canny"}, 0,
                     "sobel: 3x3 Sobel at spacing width/2 (lines about width px); canny: Sobel + non-maximum "
                     "suppression + double threshold with one-step hysteresis on normals (1 px lines)")));
    p.push_back(bool_param("depth", true, "find depth discontinuities"));
    p.push_back(float_param("depth-threshold", 0.02f, 0.0f, 10.0f,
                            "relative second difference of linear depth |z+ + z- - 2z| / z above which a pixel "
                            "is an edge (planes give 0 whatever their slope)"));
    p.push_back(bool_param("normal", true, "find creases: discontinuities of the face normal"));
    p.push_back(float_param("normal-threshold", 0.5f, 0.0f, 2.0f,
                            "Sobel magnitude of the unit face normal (a step of angle a gives 2 sin(a/2); "
                            "0.5 = 29 degrees)"));
    p.push_back(bool_param("ids", true,
                           "find object boundaries: object id = connected component x material "
                           "(render/welded_attributes.hpp); background is an object too"));
    return p;
}

const LineTypeRegistration edges_type{{
    .name = "edges",
    .summary =
        "image-space edges: Sobel/Canny on a G-buffer of depth, face normals and object ids (Saito & Takahashi 1990)",
    .space = LineSpace::Image,
    .params = edges_params(),
}};

}  // namespace
}  // namespace inkshade::render
