#include "inkshade/shading.hpp"

namespace inkshade {
// Rusinkiewicz, Burns & DeCarlo 2006, "Exaggerated Shading for Depicting Shape and Detail"
// (shaders/shading/exaggerated.frag). The finest width 0.4 edge lengths is the paper's
// implementation's (0.4 x the mesh's feature size); widths double from scale to scale (the paper
// steps by √2: doubling spans the same range of sizes with half the vertex attributes). The
// defaults a = 6 and detail 0.5 are picked by eye on scanned models, inside the ranges the
// paper shows.
static const ShadingModelRegistration exaggerated_model{{
    .name = "exaggerated",
    .summary = "exaggerated shading: C*(E*(1/2 + 1/2 sum k_i clamp(a n_i.l_i+1)) + A), l_i+1 = l grazing the "
               "coarser normal n_i+1 (Rusinkiewicz et al. 2006)",
    .fragment = "shading/exaggerated.frag",
    .inputs = {vertex_attribute_input("multiscale-normals")},
    .params =
        {
            float_param("contrast", 6.0f, 0.1f, 100.0f,
                        "a: c_i = clamp(a n_i.l_i+1, -1, 1); larger is closer to a toon shading (the paper "
                        "shows 1 to 8)"),
            float_param("detail", 0.5f, -4.0f, 4.0f,
                        "weights k_i proportional to sigma_i^-detail: 0 every scale alike, > 0 fine detail "
                        "stronger, < 0 the overall shape (the paper shows -1 to 2)"),
            compile_time(int_param("scales", 6, 1, 8,
                                   "detail scales; normals smoothed at scales + 1 widths, doubling, the coarsest "
                                   "for the base coat")),
            float_param("sigma", 0.4f, 0.01f, 100.0f,
                        "finest smoothing width in typical edge lengths (the paper's implementation: 0.4)"),
        },
}};
}  // namespace inkshade
