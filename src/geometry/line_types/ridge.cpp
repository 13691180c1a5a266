// `ridge` (optional line type): maxima of the larger principal curvature along its direction (Ohtake et al. 2004; rtsc)
// (extract_ridges).
#include "geometry/line_types/object_line_registry.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView&, const LineSettings& settings) {
    const RidgeOptions options{.threshold = line_number(settings, "threshold"),
                               .feature_size = line_number(settings, "feature-size")};
    return data.ridges(options).ridges;
}

const ObjectLineRegistration registration{
    {.name = "ridge",
     .summary = "ridges: maxima of the larger principal curvature along its direction (Ohtake et al. 2004; rtsc)",
     .params = object_line_params(
         glm::vec3(0.0f), 1.0f,
         {float_param("threshold", 0.1f, 0.0f, 100.0f,
                      "keep points where k1 > threshold / feature-size (dimensionless; rtsc's rv_thresh default 0.1)"),
          feature_size_param("threshold")},
         2.0f)},
    extract,
    {.curvature = true}};

}  // namespace

}  // namespace inkshade::geometry
