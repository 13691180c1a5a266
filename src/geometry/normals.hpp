// Face and vertex normals.
#pragma once
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// Unit normal per triangle (right-hand rule, counter-clockwise front); zero for degenerate faces.
std::vector<glm::vec3> face_normals(const Mesh& mesh);

// Angle-weighted vertex normals (Thürmer & Wüthrich 1998): each face contributes its unit
// normal times the interior angle at the vertex. Isolated vertices get (0,0,1).
std::vector<glm::vec3> angle_weighted_vertex_normals(const Mesh& mesh);

// True when normals has one finite, non-zero-length entry per vertex.
bool normals_are_sane(const Mesh& mesh);

// Keeps file normals when sane (renormalised), else computes angle-weighted ones.
void ensure_vertex_normals(Mesh& mesh);

}  // namespace inkshade::geometry
