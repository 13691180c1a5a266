// The mesh's sampling scale: how long its edges typically are, for the image-space line types
// whose finite differences must span a triangle (shaders/lines/suggestive_image.glsl).
#pragma once
#include "inkshade/mesh.hpp"

namespace inkshade::render {

// The side of the equilateral triangle whose area is the median triangle area (world units),
// from at most 65536 triangles evenly spread over the index list; 0 for a mesh without
// triangles. By area, not edge length: a sliver's long edges say nothing about how densely the
// surface is sampled across it. The median, not the mean: a few huge triangles on the flat
// faces of a CAD part do not move it.
float typical_edge_length(const Mesh& mesh);

}  // namespace inkshade::render
