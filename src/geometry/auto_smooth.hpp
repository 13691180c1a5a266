// Auto-smooth: hard edges for meshes whose files carry no normals (STL, OFF, PLY without
// nx/ny/nz, OBJ without `vn`). Averaging face normals across a sharp edge makes a cube shade
// like a sphere; splitting the shading normal at every edge whose faces meet at more than an
// angle keeps flat faces flat and curved regions smooth, as Blender's "Auto Smooth" does.
#pragma once
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// Fills mesh.shading_normals and mesh.shading_normal_ids: around each vertex, the faces
// joined across smooth edges (manifold edges whose face normals differ by at most
// `angle_degrees`) form one fan, and each fan gets one normal, its faces weighted by their angle
// at the vertex (Thürmer & Wüthrich 1998) or by their area (three.js's computeVertexNormals). Edges of three or more faces are hard; degenerate faces join no fan and
// take the vertex's smooth normal. When no edge is hard, or angle_degrees >= 180, the two
// arrays are left empty (mesh.normals shades alone). mesh.normals is not changed.
void auto_smooth(Mesh& mesh, float angle_degrees, NormalWeighting weighting = NormalWeighting::Angle);

}  // namespace inkshade::geometry
