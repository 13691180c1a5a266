#include "inkshade/shading.hpp"

namespace inkshade {
// Voronoi (cellular) shading on 3-D model-space cells (Worley 1996, "A Cellular Texture Basis
// Function"), so the pattern sticks to the surface and works on any mesh size.
static const ShadingModelRegistration voronoi_model{{
    .name = "voronoi",
    .summary = "Worley cells of normalized model position*scale: cell colours, grey F1 or F1 isolines, "
               "edges where F2-F1 < edge-width, times E*max(n.l,0)+A when lit",
    .fragment = "shading/voronoi.frag",
    .params =
        {
            float_param("scale", 8.0f, 0.25f, 256.0f, "cells per longest side of the model's bounding box"),
            // Compile-time: llvmpipe evaluates both sides of a uniform branch, so the isolines'
            // and the cell colours' work would be paid in every mode.
            compile_time(choice_param(
                "mode", {"cells", "distance", "isolines"}, 0,
                "cells: flat colour per cell; distance: grey F1; isolines: lines of equal F1 (concentric rings)")),
            float_param("color-mix", 0.8f, 0.0f, 1.0f, "cells mode: 0 = base colour C, 1 = the cell's hashed colour"),
            float_param("edge-width", 0.05f, 0.0f, 1.0f,
                        "cell borders where F2 - F1 < width, in cell units (0 = none); anti-aliased"),
            color_param("edge-color", glm::vec3(0.0f), "colour of cell borders and isolines"),
            float_param("isoline-spacing", 0.2f, 0.01f, 1.0f, "isolines mode: F1 between lines, in cell units"),
            compile_time(bool_param("lit", true, "multiply by E*max(n.l,0) + A")),
        },
}};
}  // namespace inkshade
