#include "inkshade/shading.hpp"

namespace inkshade {
// Inigo Quilez, "palettes" (iquilezles.org/articles/palettes), a common cosine palette; the
// defaults are his rainbow example a = b = 0.5, c = 1, d = (0, 0.33, 0.67). c and d are lists
// (1 or 3 values; one value repeats) because their ranges exceed a colour's [0, 1].
static const ShadingModelRegistration palette_model{{
    .name = "palette",
    .summary = "a + b*cos(2*pi*(c*t + d)), t = max(n.l,0) or another driver; optionally lit",
    .fragment = "shading/palette.frag",
    .params =
        {
            color_param("a", glm::vec3(0.5f), "offset (mean colour)"),
            color_param("b", glm::vec3(0.5f), "amplitude"),
            list_param("c", {1.0f, 1.0f, 1.0f}, 3, 0.0f, 4.0f, "frequency per channel (oscillations over t in [0, 1])"),
            list_param("d", {0.0f, 0.33f, 0.67f}, 3, 0.0f, 1.0f, "phase per channel, in cycles"),
            choice_param(
                "driver", {"ndotl", "half-lambert", "ndotv", "height", "x", "z"}, 0,
                "t: max(n.l,0), 0.5*n.l+0.5, max(n.v,0), or model-space y, x, z normalised over the bounding box"),
            bool_param("lit", false, "multiply by E*max(n.l,0) + A"),
        },
}};
}  // namespace inkshade
