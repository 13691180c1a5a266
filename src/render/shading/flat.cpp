#include "inkshade/shading.hpp"

namespace inkshade {
static const ShadingModelRegistration flat_model{{
    .name = "flat",
    .summary = "Lambert with one normal per face from dFdx(p) x dFdy(p): C*(E*max(n.l,0) + A)",
    .fragment = "shading/flat.frag",
}};
}  // namespace inkshade
