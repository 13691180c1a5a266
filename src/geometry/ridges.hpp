// Ridges and valleys (optional line types `ridge`, `valley`): view-independent lines where a
// principal curvature has an extremum along its own direction — zero crossings of
// e1 = ∂k1/∂s1 (C111) where k1 is large and positive, and of e2 = ∂k2/∂s2 (C222) where k2 is
// large and negative (Ohtake, Belyaev & Seidel 2004's definition; rtsc's draw_mesh_ridges
// with the derivative tensor of Rusinkiewicz 2004).
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "geometry/curvature.hpp"

namespace inkshade::geometry {

struct RidgeOptions {
    // Keep a crossing where |k| > threshold / feature_size there (rtsc's rv_thresh, 0.1).
    float threshold = 0.1f;
    // World units; 0 = line_feature_size(mesh, curvature) (feature_size.hpp), as for suggestive
    // contours.
    float feature_size = 0.0f;
};

struct RidgeLines {
    std::vector<LineSegment> ridges;   // maxima of k1 along pdir1, k1 > 0
    std::vector<LineSegment> valleys;  // minima of k2 along pdir2, k2 < 0
};

// Ridge and valley segments in face order, strength 1. The principal direction is a line
// field (no sign), so each edge orients its far end's direction to agree with its lower
// index's and decides its crossing alone: neighbouring faces share bit-identical points and
// edge keys. A face with two crossing edges gives a segment (a → b in no particular sense);
// one with three (near an umbilic, where the field turns) gives none. Throws
// std::invalid_argument when curvature does not have one entry per vertex.
RidgeLines extract_ridges(const Mesh& mesh, const Curvature& curvature, const RidgeOptions& options = {});

}  // namespace inkshade::geometry
