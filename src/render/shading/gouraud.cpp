#include "inkshade/shading.hpp"

namespace inkshade {
static const ShadingModelRegistration gouraud_model{{
    .name = "gouraud",
    .summary = "Lambert per vertex, colour interpolated: C*(E*max(n.l,0) + A)",
    .fragment = "shading/gouraud.frag",
    .vertex = "shading/gouraud.vert",
}};
}  // namespace inkshade
