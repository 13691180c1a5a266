#include "inkshade/shading.hpp"

namespace inkshade {
// The intermediate passes of image-space suggestive contours (normals, view vectors, their
// tangent projection w, n.v; as shown in Qu, Chen & Zwicker 2022, "Non-Photorealistic Shading
// Techniques for Anime-Style Rendering", fig. 8), as debug views, and the radial curvature they
// approximate (DeCarlo et al. 2003).
static const ShadingModelRegistration normal_view{{.name = "normal",
                                                   .summary = "world-space normal, 0.5*n + 0.5",
                                                   .fragment = "debug/normal.frag",
                                                   .debug_view = true}};
static const ShadingModelRegistration view_view{{.name = "view",
                                                 .summary = "world-space view vector v, 0.5*v + 0.5",
                                                 .fragment = "debug/view.frag",
                                                 .debug_view = true}};
static const ShadingModelRegistration w_view{{.name = "w",
                                              .summary = "tangent projection w = v - (n.v)n, 0.5*w + 0.5",
                                              .fragment = "debug/w.frag",
                                              .debug_view = true}};
static const ShadingModelRegistration ndotv_view{
    {.name = "ndotv", .summary = "grey level n.v", .fragment = "debug/ndotv.frag", .debug_view = true}};
static const ShadingModelRegistration kr_view{
    {.name = "kr",
     .summary = "radial curvature kr (DeCarlo et al. 2003): red > 0, white 0, blue < 0; suggestive contours "
                "lie on kr = 0 where it grows towards the contour",
     .fragment = "debug/kr.frag",
     .debug_view = true,
     .inputs = {vertex_attribute_input("radial-curvature")},
     .params = {float_param("range", 0.15f, 1e-5f, 100.0f,
                            "kr x feature size (1% of the bounding-box diagonal) shown at full colour")}}};
}  // namespace inkshade
