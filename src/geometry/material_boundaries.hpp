// Material boundaries (line type `material-boundary`): mesh edges between faces of different
// materials (Mesh::face_materials). Edges are matched by the positions of their ends, not only
// by index, since a model keeps each material's faces apart (a glTF primitive each) and they
// meet at coincident copies of the boundary's vertices.
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// One segment per boundary edge, sorted by its ends' canonical vertices (canonical_vertices):
// ends at those vertices (vertex_key), face = the lowest face of the edge, strength 1. None
// when the mesh has no per-face materials (face_materials.size() != triangles.size()) or one
// material only. Faces with an index out of range or repeated are left out.
std::vector<LineSegment> extract_material_boundaries(const Mesh& mesh);

}  // namespace inkshade::geometry
