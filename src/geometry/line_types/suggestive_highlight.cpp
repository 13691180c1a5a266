// `suggestive-highlight`: κr = 0 with D_w κr < 0, the other half of the zeros of the radial
// curvature (DeCarlo & Rusinkiewicz 2007), trimmed and faded as rtsc does
// (extract_suggestive_contours with highlights).
#include "geometry/line_types/object_line_registry.hpp"
#include "geometry/suggestive_contours.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& view, const LineSettings& settings) {
    const float size = line_number(settings, "feature-size");
    const SuggestiveOptions options{.threshold = line_number(settings, "threshold"),
                                    .fade = line_number(settings, "fade"),
                                    .feature_size = size > 0.0f ? size : data.feature_size(),
                                    .highlights = true};
    return extract_suggestive_contours(data.mesh(), data.normals(), data.curvature(), view.camera, options);
}

const ObjectLineRegistration registration{
    {.name = "suggestive-highlight",
     .summary = "suggestive highlights: κr = 0 with D_w κr < 0 (DeCarlo & Rusinkiewicz 2007; trim and fade as rtsc)",
     .params = object_line_params(
         glm::vec3(0.3f), 1.0f,
         {float_param("threshold", 0.02f, 0.0f, 10.0f,
                      "trim: keep points where −D_w κr / (n·v) > threshold / feature-size² (dimensionless; rtsc's "
                      "sh_thresh default 0.02)"),
          float_param("fade", 0.03f, 0.0f, 10.0f,
                      "fade-in above the trim threshold, in the same units (rtsc's draw_faded constant 0.03); "
                      "0 = no fading"),
          feature_size_param("threshold and fade")},
         0.0f)},  // as `suggestive`: rtsc draws every trimmed piece
    extract,
    {.curvature = true}};

}  // namespace

}  // namespace inkshade::geometry
