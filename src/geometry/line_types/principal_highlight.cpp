// `principal-highlight`: where n·v has a strong maximum along the principal direction of
// larger curvature magnitude (DeCarlo & Rusinkiewicz 2007; rtsc's draw_mesh_ph)
// (extract_principal_highlights).
#include "geometry/line_types/object_line_registry.hpp"
#include "geometry/principal_highlights.hpp"

namespace inkshade::geometry {

namespace {

std::vector<LineSegment> extract(MeshLineData& data, const LineView& view, const LineSettings& settings) {
    const float size = line_number(settings, "feature-size");
    const PrincipalHighlightOptions options{.threshold = line_number(settings, "threshold"),
                                            .fade = line_number(settings, "fade") != 0.0f,
                                            .convex = line_number(settings, "convex") != 0.0f,
                                            .concave = line_number(settings, "concave") != 0.0f,
                                            .feature_size = size > 0.0f ? size : data.feature_size()};
    return extract_principal_highlights(data.mesh(), data.normals(), data.curvature(), view.camera, options);
}

const ObjectLineRegistration registration{
    {.name = "principal-highlight",
     .summary = "principal highlights: strong maxima of n·v along the principal direction of larger |k| "
                "(DeCarlo & Rusinkiewicz 2007; rtsc)",
     .params = object_line_params(
         glm::vec3(0.0f), 1.0f,
         {float_param("threshold", 0.04f, 0.0f, 100.0f,
                      "keep points where (k1² − k2²)(n·v) > threshold / feature-size², k1 the larger-magnitude "
                      "curvature (dimensionless; rtsc's ph_thresh default 0.04)"),
          bool_param("fade", true, "strength rises from 0 at the threshold (rtsc's draw_faded); false: strength 1"),
          bool_param("convex", true, "where k1 > 0: bumps, a cylinder from outside (rtsc's Principal Hlt. (R))"),
          bool_param("concave", true, "where k1 < 0: grooves (rtsc's Principal Hlt. (V))"),
          feature_size_param("threshold")},
         2.0f)},
    extract,
    {.curvature = true}};

}  // namespace

}  // namespace inkshade::geometry
