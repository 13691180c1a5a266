// `suggestive`: object-space suggestive contours of DeCarlo et al. 2003 (the image-space method is
// `suggestive-image`), trimmed and faded as in DeCarlo et al. 2004 / rtsc
// (extract_suggestive_contours).
#include "geometry/line_types/object_line_registry.hpp"
#include "geometry/suggestive_contours.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& view, const LineSettings& settings) {
    const float size = line_number(settings, "feature-size");
    const SuggestiveOptions options{.threshold = line_number(settings, "threshold"),
                                    .fade = line_number(settings, "fade"),
                                    .feature_size = size > 0.0f ? size : data.feature_size()};
    return extract_suggestive_contours(data.mesh(), data.normals(), data.curvature(), view.camera, options);
}

const ObjectLineRegistration registration{
    {.name = "suggestive",
     .summary = "suggestive contours: κr = 0 with D_w κr > 0 (DeCarlo et al. 2003; trim and fade as rtsc)",
     .params = object_line_params(
         glm::vec3(0.0f), 1.0f,
         {float_param("threshold", 0.01f, 0.0f, 10.0f,
                      "trim: keep points where D_w κr / (n·v) > threshold / feature-size² (dimensionless; "
                      "rtsc's sug_thresh default 0.01)"),
          float_param("fade", 0.03f, 0.0f, 10.0f,
                      "fade-in above the trim threshold, in the same units (rtsc's draw_faded constant 0.03); "
                      "0 = no fading"),
          feature_size_param("threshold and fade")},
         // No length filter by default: rtsc 1.6 draws every trimmed piece (DeCarlo 2003 §4's
         // 4 px filter is `min-length = 4`).
         0.0f)},
    extract,
    {.curvature = true, .own_slope = true}};

}  // namespace

}  // namespace inkshade::geometry
