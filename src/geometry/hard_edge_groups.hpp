// Hard edges that are features, not noise (auto_smooth.hpp, docs/inputs.md "Normals and hard
// edges"). On a CAD part the hard edges join into networks: a cube's twelve, fandisk's 718 in
// one, a rotor's nine groups of dozens. On a scan the ones that survive hard_edges.hpp's side
// test are decimation folds and spikes: a lone edge, a dash of two, a sliver triangle's three,
// now and then a dozen joined. Counted on CGAL's meshes and the Stanford dragon: every group of
// the CAD parts has 12 edges or more; 93-99.9 % of a scan's groups have fewer.
#pragma once
#include <cstdint>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// Edges per group below which a group of hard edges is taken for noise.
constexpr size_t kMinHardEdgeGroup = 12;

// Clears, in `flags` (HardEdgeFlags::flags: bit k of face f for its edge from corner k to k + 1),
// every hard edge of a group (hard edges joined at their vertices) of fewer than `min_edges`
// distinct edges whose vertices' bounding box is under a tenth of the model's diagonal (a
// small solid, a tetrahedron or a wedge, keeps its few edges). Triangles must index existing
// vertices.
void drop_small_hard_edge_groups(const Mesh& mesh, std::vector<uint8_t>& flags, size_t min_edges = kMinHardEdgeGroup);

}  // namespace inkshade::geometry
