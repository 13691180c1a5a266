// Chaining line segments into polylines by the mesh edge each endpoint lies on.
#pragma once
#include <vector>

#include "geometry/contours.hpp"

namespace inkshade::geometry {

struct Polyline {
    std::vector<glm::vec3> points;  // a closed polyline does not repeat its first point
    bool closed = false;
};

// Joins segments that share an edge key into polylines, in O(n) (hash map from edge key to
// segment ends). A node (edge key) with one segment end, or more than two (non-manifold), ends
// a chain; chains through nodes of degree two only are closed loops. Output order is
// deterministic: first the open chains, in the order of the first segment end (by segment
// index, a before b) at a chain-ending node; then the loops, by their lowest segment index.
// Each polyline runs along its first segment's a → b direction (an open chain walked from that
// segment's b end is reversed), so on a consistently oriented mesh a contour keeps the
// front-facing side on its left. Segments whose two ends share a key are dropped.
std::vector<Polyline> chain_segments(const std::vector<ContourSegment>& segments);

}  // namespace inkshade::geometry
