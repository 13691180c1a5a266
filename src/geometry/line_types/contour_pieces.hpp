// The occluding contour as `contour` extracts it, and its pieces by what lies behind them
// (contour_backgrounds.hpp), for `silhouette` and `external-contour`.
#pragma once
#include <vector>

#include "geometry/contour_backgrounds.hpp"
#include "geometry/line_types/object_line_registry.hpp"

namespace inkshade::geometry {

// n·v = 0 interpolated across faces, or on a mesh with hard edges with the facing flips at
// them (extract_hard_edge_contours).
std::vector<LineSegment> occluding_contours(MeshLineData& data, const Camera& camera);

// The occluding contour's segments whose background `keep` accepts.
std::vector<LineSegment> contour_pieces(MeshLineData& data, const LineView& view, bool (*keep)(Behind));

}  // namespace inkshade::geometry
