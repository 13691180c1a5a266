// The objects of a mesh: its connected pieces, faces joined where they share a vertex position
// (canonical_vertices), so a seam or a material's own primitive does not split an object. The
// line types `silhouette` and `external-contour` tell an object's outline from its inner folds
// with them (docs/lines.md).
#pragma once
#include <cstdint>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// Per face, the lowest canonical vertex of its object (a label, equal for the faces of one
// object). Faces with an index out of range get kNoObject.
constexpr uint32_t kNoObject = 0xffffffffu;
std::vector<uint32_t> face_objects(const Mesh& mesh);

}  // namespace inkshade::geometry
