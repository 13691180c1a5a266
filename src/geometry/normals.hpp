// Face and vertex normals.
#pragma once
#include <cmath>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// Unit normal of triangle (a, b, c) (right-hand rule, counter-clockwise front), in double
// precision; zero when it has no direction (degenerate face, overflow, NaN input).
inline glm::vec3 unit_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 n = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
    const double len = glm::length(n);
    if (!(len > 0.0) || !std::isfinite(len)) return glm::vec3(0.0f);
    return glm::vec3(n / len);
}

// Interior angle between edges u and v in radians, 0 when undefined; atan2 stays accurate for
// nearly flat angles where acos of the normalised dot product loses precision.
inline float angle_between(const glm::vec3& u, const glm::vec3& v) {
    const float a = std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
    return std::isfinite(a) ? a : 0.0f;
}

// unit_normal per triangle; zero for degenerate faces and ones with an out-of-range index.
std::vector<glm::vec3> face_normals(const Mesh& mesh);

// Angle-weighted vertex normals (Thürmer & Wüthrich 1998): each face contributes its unit
// normal times the interior angle at the vertex. Isolated vertices get (0,0,1).
std::vector<glm::vec3> angle_weighted_vertex_normals(const Mesh& mesh);
// The same from the mesh's face normals `fn` (face_normals), for a caller that needs them too.
std::vector<glm::vec3> angle_weighted_vertex_normals(const Mesh& mesh, const std::vector<glm::vec3>& fn);

// Area-weighted vertex normals, as three.js's BufferGeometry.computeVertexNormals: each face
// contributes its cross product (b - a) x (c - a), twice its area times its unit normal.
// Isolated vertices get (0,0,1).
std::vector<glm::vec3> area_weighted_vertex_normals(const Mesh& mesh);

// The weight of face f's unit normal at its corner k (0..2) under `weighting`.
float corner_weight(const Mesh& mesh, size_t f, int k, NormalWeighting weighting);

// True when normals has one finite, non-zero-length entry per vertex.
bool normals_are_sane(const Mesh& mesh);

// Keeps file normals when sane (renormalised), else computes them weighted as asked.
void ensure_vertex_normals(Mesh& mesh, NormalWeighting weighting = NormalWeighting::Angle);

}  // namespace inkshade::geometry
