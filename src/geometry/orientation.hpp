// Whether a mesh is a closed, consistently and outward oriented surface.
#pragma once
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// True when every edge is shared by exactly two faces that traverse it in opposite directions
// and the enclosed signed volume is positive. From outside such a surface no back face is
// ever visible, so the renderer may cull them (half the triangle setup on llvmpipe).
bool is_closed_outward(const Mesh& mesh);

}  // namespace inkshade::geometry
