// `suggestive-image`: the image-space suggestive contours of Qu, Chen & Zwicker 2022, "Non-Photorealistic Shading
// Techniques for Anime-Style Rendering" (section 3.8), computed on the GPU by ImageLinesPass
// (shaders/lines/suggestive_image.glsl).
#include "inkshade/lines.hpp"

namespace inkshade::render {
namespace {

std::vector<ParamSpec> suggestive_params() {
    std::vector<ParamSpec> p = stroke_params(glm::vec3(0.0f), 1.5f);
    p.push_back(int_param("step", 2, 1, 8, "smallest finite-difference spacing h in pixels (Qu et al. 2022 use 1)"));
    p.push_back(float_param("edge-span", 1.0f, 0.0f, 64.0f,
                            "the spacing spans this many of the mesh's typical edge lengths (at least step px): "
                            "kinks of interpolated normals at the edges of coarse meshes average out; 0 = step"));
    p.push_back(float_param("threshold", 20.0f, 0.0f, 1e6f,
                            "minimum D_w D_w(n.v), derivatives per image height, the valley sharpness "
                            "DeCarlo et al. 2003 threshold (section 4)"));
    p.push_back(float_param("fade", 40.0f, 0.0f, 1e6f,
                            "lines fade in over D_w D_w(n.v) in [threshold, threshold + fade] "
                            "(DeCarlo et al. 2004 fade by strength)"));
    p.push_back(float_param("min-ndotv", 0.2f, 0.0f, 1.0f,
                            "no lines where n.v is below this, fading in up to twice this: close to "
                            "contours w turns unstable and tessellation noise grows"));
    return p;
}

const LineTypeRegistration suggestive_image_type{{
    .name = "suggestive-image",
    .summary = "image-space suggestive contours: D_w(n.v) = 0, D_w D_w(n.v) > 0 by finite differences on the GPU "
               "(DeCarlo et al. 2003; finite differences as in Qu et al. 2022)",
    .space = LineSpace::Image,
    .params = suggestive_params(),
}};

}  // namespace
}  // namespace inkshade::render
