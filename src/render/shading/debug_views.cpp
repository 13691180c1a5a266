#include "inkshade/shading.hpp"

namespace inkshade {
// Seed 000's intermediate passes for suggestive contours (fig. 8), as debug views.
static const ShadingModelRegistration normal_view{{
    .name = "normal", .summary = "world-space normal, 0.5*n + 0.5", .fragment = "debug/normal.frag",
    .debug_view = true}};
static const ShadingModelRegistration view_view{{
    .name = "view", .summary = "world-space view vector v, 0.5*v + 0.5", .fragment = "debug/view.frag",
    .debug_view = true}};
static const ShadingModelRegistration w_view{{
    .name = "w", .summary = "tangent projection w = v - (n.v)n, 0.5*w + 0.5", .fragment = "debug/w.frag",
    .debug_view = true}};
static const ShadingModelRegistration ndotv_view{{
    .name = "ndotv", .summary = "grey level n.v", .fragment = "debug/ndotv.frag", .debug_view = true}};
}  // namespace inkshade
