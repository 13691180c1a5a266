// Per-vertex and per-face attributes that must not see the seams of a split mesh: vertices
// with identical positions (split normals at creases, UV or material seams) count as one.
// Pure functions over the mesh; the GPU mesh uploads their results.
#pragma once
#include <cstdint>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::render {

// One index per vertex naming the first vertex with exactly the same position (bitwise equal
// coordinates: seams written by exporters repeat the position exactly; near-coincident soups
// are welded by the loaders already, geometry/weld.hpp).
std::vector<uint32_t> position_classes(const Mesh& mesh);

// Angle-weighted normals (Thürmer & Wüthrich 1998) accumulated over position classes, so every
// copy of a split vertex gets the same averaged normal: the inverted hull extrudes along these
// and does not crack open at creases or split normals.
std::vector<glm::vec3> welded_vertex_normals(const Mesh& mesh);

// Object id per triangle, from 1 (0 = background): connected components of the
// position-welded mesh, further split by material, numbered in order of first face. Two
// touching but unconnected parts, or two materials, are different objects for `edges`.
// With `parts`, parts[id - 1] = (part, material) of each object id: its connected part, from 1 in
// order of first face, and its material index + 1 (1 without per-face materials), as the
// id and material AOVs number them.
std::vector<uint32_t> face_object_ids(const Mesh& mesh, std::vector<glm::uvec2>* parts = nullptr);

}  // namespace inkshade::render
