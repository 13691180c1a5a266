#include "inkshade/shading.hpp"

namespace inkshade {
// Gooch et al. 1998, "A Non-Photorealistic Lighting Model for Automatic Technical
// Illustration": defaults b = y = 0.4, alpha = 0.2, beta = 0.6 are the paper's.
static const ShadingModelRegistration gooch_model{{
    .name = "gooch",
    .summary = "t*(k_yellow + beta*C) + (1-t)*(k_blue + alpha*C), t = (1 + n.l)/2; optional white Phong highlight",
    .fragment = "shading/gooch.frag",
    .params =
        {
            float_param("blue", 0.4f, 0.0f, 1.0f, "b of k_blue = (0, 0, b) (Gooch et al. 1998: 0.4)"),
            float_param("yellow", 0.4f, 0.0f, 1.0f, "y of k_yellow = (y, y, 0) (Gooch et al. 1998: 0.4)"),
            float_param("alpha", 0.2f, 0.0f, 1.0f, "share of C in the cool colour (Gooch et al. 1998: 0.2)"),
            float_param("beta", 0.6f, 0.0f, 1.0f, "share of C in the warm colour (Gooch et al. 1998: 0.6)"),
            bool_param("specular", false, "add a white highlight max(r.v, 0)^shininess where n.l > 0"),
            float_param("shininess", 32.0f, 1.0f, 4096.0f, "highlight exponent (as phong)"),
        },
}};
}  // namespace inkshade
