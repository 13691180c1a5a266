#include "inkshade/shading.hpp"

namespace inkshade {
static const ShadingModelRegistration lambert_model{{
    .name = "lambert",
    .summary = "Lambert per pixel with interpolated normals: C*(E*max(n.l,0) + A)",
    .fragment = "shading/lambert.frag",
}};
}  // namespace inkshade
