// Auto-smooth: hard edges for meshes whose files carry no normals (STL, OFF, PLY without
// nx/ny/nz, OBJ without `vn`). Averaging face normals across a sharp edge makes a cube shade
// like a sphere; splitting the shading normal at every edge whose faces meet at more than an
// angle keeps flat faces flat and curved regions smooth, as Blender's "Auto Smooth" does.
#pragma once
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// Fills mesh.shading_splits (mesh.hpp): around each vertex, the faces joined across smooth
// edges form one fan, and at a vertex of several fans each gets one normal, its faces weighted
// by their angle at the vertex (Thürmer & Wüthrich 1998) or by their area (three.js's
// computeVertexNormals). Hard edges (hard_edge_flags, hard_edges.hpp): edges of three or more
// faces, and edges whose faces meet at more than `angle_degrees` and whose sides, averaged over
// the faces around them, still do (so a scan's noise splits nothing). A vertex of one fan keeps
// its smooth normal mesh.normals[v]; degenerate faces join the fan of a vertex that has one, and
// a fan of degenerate faces alone takes the smooth normal. When no vertex has two fans, or
// angle_degrees >= 180, or mesh.normals does not have one normal per vertex, shading_splits is
// left empty (mesh.normals shades alone). mesh.normals is not changed.
void auto_smooth(Mesh& mesh, float angle_degrees, NormalWeighting weighting = NormalWeighting::Angle);
// The same with the mesh's face normals `fn` (face_normals) made by the caller, who needed
// them for the vertex normals too (load_mesh): a scan's load then computes them once.
void auto_smooth(Mesh& mesh, float angle_degrees, NormalWeighting weighting, const std::vector<glm::vec3>& fn);

}  // namespace inkshade::geometry
