// `apparent-ridge` (optional line type): maxima of the view-dependent curvature along its
// direction in the image (Judd, Durand & Adelson 2007; rtsc) (extract_apparent_ridges).
#include "geometry/apparent_ridges.hpp"
#include "geometry/line_types/object_line_registry.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& view, const LineSettings& settings) {
    const float size = line_number(settings, "feature-size");
    const ApparentRidgeOptions options{.threshold = line_number(settings, "threshold"),
                                       .feature_size = size > 0.0f ? size : data.feature_size()};
    return extract_apparent_ridges(data.mesh(), data.normals(), data.curvature(), view.camera, options);
}

const ObjectLineRegistration registration{
    {.name = "apparent-ridge",
     .summary = "apparent ridges: maxima of the view-dependent curvature q1 along its image direction t1 (Judd et "
                "al. 2007; threshold and fade as rtsc)",
     .params = object_line_params(
         glm::vec3(0.0f), 1.5f,
         {float_param("threshold", 0.1f, 0.0f, 100.0f,
                      "keep points where q1² > threshold / feature-size² (dimensionless; rtsc's ar_thresh default "
                      "0.1); lines fade in above it as 1 − threshold / (q1² feature-size²)"),
          feature_size_param("threshold")},
         2.0f)},
    extract,
    {.curvature = true}};

}  // namespace

}  // namespace inkshade::geometry
