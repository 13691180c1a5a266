#include "inkshade/shading.hpp"

namespace inkshade {
// Stippling (dots of ink, more of them where the surface is darker), with dots attached to the
// surface (3-D jittered lattice in model space) and kept at a constant size in pixels
// (power-of-two lattice level from the pixel footprint, two levels blended). Method and
// references: docs/shading.md.
static const ShadingModelRegistration stipple_model{{
    .name = "stipple",
    .summary = "ink dots of fixed pixel size on a surface-attached 3-D lattice; their number grows with "
               "darkness (1 - luminance(E*max(n.l,0)+A))^threshold-curve",
    .fragment = "shading/stipple.frag",
    .params =
        {
            float_param("dot-size", 3.0f, 1.0f, 32.0f, "dot diameter in pixels, the same at any zoom"),
            float_param("density", 0.5f, 0.05f, 1.0f,
                        "dots per dot-size^2 pixels in full dark (0.5: about 40% ink coverage)"),
            color_param("ink-color", glm::vec3(0.08f, 0.08f, 0.1f),
                        "dot colour, times C (dots take the diffuse colour)"),
            color_param("paper-color", glm::vec3(1.0f), "colour between the dots"),
            float_param("threshold-curve", 1.0f, 0.1f, 8.0f,
                        "gamma on darkness: > 1 keeps mid-tones lighter, < 1 darker"),
        },
}};
}  // namespace inkshade
