// Dashed strokes: a stroke cut into dashes along its arc length by an on/off pattern in pixels
// (Freestyle's DashedLineShader; Blender's line style "Dashed Line": dash 1, gap 1, dash 2, ...;
// SVG's stroke-dasharray, whose odd-length lists repeat). Cut in the image, not by the SVG
// viewer, so GPU strokes and SVG draw the same dashes and each dash keeps the widths and colours
// of its part of the stroke.
#pragma once
#include <vector>

#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {

// The dashes of `paths`: pattern = on, off, on, off, ... lengths in pixels (an odd count is
// repeated once, as SVG does). The pattern starts anew at each path's start; a loop is opened at
// its first point. An empty pattern, or one of zeros, returns the paths unchanged.
std::vector<LinePath> dash_paths(const std::vector<LinePath>& paths, const std::vector<float>& pattern);

}  // namespace inkshade::geometry
