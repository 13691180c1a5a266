// Colour along a stroke: the layer's colour blended towards a second colour by depth (near →
// far; Blender's line style colour modifier "Distance from Camera") or along the stroke's arc
// length (start → end; "Along Stroke").
#pragma once
#include <vector>

#include "geometry/view_depth_range.hpp"
#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {

enum class ColorAlong { None, Depth, Length };

// The colour of each point of `path`: mix(start, end, t) with t the point's depth fraction
// (ColorAlong::Depth) or its arc length over the path's length (Length; a loop's first point
// is its start). Empty for ColorAlong::None.
std::vector<glm::vec3> stroke_colors(const LinePath& path, ColorAlong along, glm::vec3 start, glm::vec3 end,
                                     const ViewDepthRange& depth);

}  // namespace inkshade::geometry
