// Creases and borders (line types `crease`, `border`): view-independent lines made of whole mesh
// edges, as segments with vertex node keys so chain_segments joins them through vertices.
#pragma once
#include <vector>

#include "geometry/adjacency.hpp"
#include "geometry/contours.hpp"

namespace inkshade::geometry {

struct CreaseOptions {
    // An edge is a crease where its two face normals differ by more than this (degrees). 60°
    // (issue 6's default): facets of a tessellated curved surface meet at far less, the faces of
    // a box at 90°.
    float angle_degrees = 60.0f;
};

// Feature edges, each list in edge order (sorted by vertex pair). Segments run from the lower to
// the higher vertex index, have strength 1, node keys vertex_key(v) and `face` = the lowest
// incident face.
struct CreaseLines {
    std::vector<LineSegment> ridges;   // convex creases: the surface folds away from its normal
    std::vector<LineSegment> valleys;  // concave creases: it folds towards its normal
    std::vector<LineSegment> borders;  // edges of exactly one face (mesh boundary)
    // Edges of three or more faces. Drawn as creases whatever the angle (decision: a fin or
    // T-junction is a visible feature, and no single dihedral angle is defined there).
    std::vector<LineSegment> non_manifold;
};

// Classifies every edge of `adjacency` (built from `mesh`). For a two-face edge the fold is
// measured between the face normals; when the two faces traverse the edge in the same
// direction (inconsistent orientation) the second normal is flipped first, so an orientation
// seam is not taken for a crease. Edges touching a zero-area face are neither creases nor
// valleys (no normal), but still count as borders or non-manifold by their face count.
CreaseLines extract_creases(const Mesh& mesh, const EdgeAdjacency& adjacency, const CreaseOptions& options = {});

}  // namespace inkshade::geometry
