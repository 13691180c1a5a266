// Vertices at one position: a model's parts (a glTF primitive per material, a UV seam) share
// positions, not indices, where they meet.
#pragma once
#include <cstdint>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// For each vertex, the lowest index of a vertex at exactly the same position (bitwise, so
// coincident copies match and nothing else does). O(V) expected.
std::vector<uint32_t> canonical_vertices(const Mesh& mesh);

}  // namespace inkshade::geometry
