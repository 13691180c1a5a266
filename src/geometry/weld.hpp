// Welding a triangle soup into an indexed mesh.
#pragma once
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

struct WeldOptions {
    // Positions closer than epsilon * bounding-box diagonal are merged.
    float relative_epsilon = 1e-6f;
};

// Merges vertices whose positions coincide within the epsilon. Per-vertex attributes
// (normals, colours, uvs) of the first vertex of each cluster are kept. Triangles that
// collapse (two equal indices) are kept: degenerate faces still render and are counted
// by mesh_stats. Sets mesh.welded = true when any vertex was merged. O(n) expected via
// a spatial hash.
void weld(Mesh& mesh, const WeldOptions& options = {});

}  // namespace inkshade::geometry
