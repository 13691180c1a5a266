// The surface location of each point of a drawing's paths (LinePath::surface, --lines-json-detail
// full): made from the chains' world points and faces, carried through every path operation by
// path_attributes.hpp, and finished here with each point's barycentric weights on its face.
#pragma once
#include <vector>

#include "geometry/chaining.hpp"
#include "geometry/visibility.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// The surface points of a chain (its world points and Polyline::faces, which must be filled;
// kNoFace as -1), with w from the view.
std::vector<SurfacePoint> surface_points(const Polyline& chain, const ImageProjection& view);

// Fills SurfacePoint::barycentric of every path point with a face: the weights of the face's
// corners that give the world point's projection on the face's plane (Ericson 2005, "Real-Time
// Collision Detection" §3.4, by dot products), computed in double; zero without a face.
void fill_barycentrics(const Mesh& mesh, std::vector<LinePath>& paths);

}  // namespace inkshade::geometry
