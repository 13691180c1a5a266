// Arc length along an image path (LinePath: pixels) and its pieces between two arc lengths, the
// per-point attributes (geometry/path_attributes.hpp) interpolated at the cut points: what
// chain splitting, dashes and the thickness modifiers measure along.
#pragma once
#include <vector>

#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {

// Cumulative arc length at each point, starting at 0 (pixels); for a closed path one more
// entry, the length back to the first point.
std::vector<double> arc_lengths(const LinePath& path);

// The path as an open polyline: a closed one gets its first point (and attributes) repeated at
// the end; an open one is returned unchanged.
LinePath opened(const LinePath& path);

// A closed path rotated to start at point k (still closed).
LinePath rotated(const LinePath& path, size_t k);

// The piece of the open path `open` between arc lengths s0 < s1 (`s` = arc_lengths(open)):
// the points strictly inside and two interpolated end points. Level copied, not closed.
LinePath sub_path(const LinePath& open, const std::vector<double>& s, double s0, double s1);

}  // namespace inkshade::geometry
