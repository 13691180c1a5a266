// Duplicate faces: a face whose vertex set equals an earlier face's (the same three indices in
// any order, so either winding). Scans hold them (the 48k Stanford dragon has over a thousand);
// load_mesh drops them and mesh_stats counts them, both through this one definition.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// One flag per face: 1 when an earlier face has the same vertex set (the first occurrence is
// 0). Indices are compared as given (weld first to compare positions); they need not be in
// range. O(n log n): packed keys sorted in parallel (TBB), no node-based maps.
std::vector<uint8_t> find_duplicate_faces(const std::vector<glm::uvec3>& triangles);

// Removes the faces find_duplicate_faces flags, keeping the order of the others and
// face_materials, face_objects and face_marks in step. Vertices are left alone. Returns the
// number of faces removed.
size_t drop_duplicate_faces(Mesh& mesh);

}  // namespace inkshade::geometry
