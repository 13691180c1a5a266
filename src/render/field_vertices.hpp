// The per-vertex values behind the surface-field AOVs (docs/aov.md): what surface_fields.hpp
// interpolates at each pixel. Mesh-wide ones (principal curvatures and directions, smoothed
// normals) come from the line extractor's cached data (MeshLineData), the view-dependent ones
// (κr, D_w κr) are computed per view as the suggestive contours compute them.
#pragma once
#include <vector>

#include "inkshade/aov.hpp"

namespace inkshade::render {

struct FieldVertices {
    std::vector<glm::vec3> normals;                // unit, the curvature's (ndotv)
    std::vector<float> kr, dwkr;                   // this view's (geometry::radial_curvature)
    std::vector<float> k1, k2;                     // k1 >= k2 (geometry::compute_curvature)
    std::vector<glm::vec3> pdir1, pdir2;           // unit, world
    std::vector<std::vector<glm::vec3>> smoothed;  // shading-scales' normals, finest first
    FieldScales scales;                            // feature size and smoothing widths (p90 per image)
};

// The smoothing widths of shading-scales: the exaggerated model's defaults (its "sigma" 0.4
// typical edge lengths, doubling; Rusinkiewicz et al. 2006), kShadingScales of them.
std::vector<float> shading_sigmas(float edge_length);

}  // namespace inkshade::render
