// Procedural models usable anywhere a file path is ("builtin:NAME"), with analytic normals.
#pragma once
#include <string>
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::builtin {

// Unit sphere at the origin: UV sphere with `rings` latitude bands and `segments` longitudes,
// welded (poles shared), normals = positions.
Mesh sphere(int rings = 64, int segments = 128, float radius = 1.0f);

// Torus around the z axis: major radius R (centre of tube), minor radius r.
Mesh torus(float major_radius = 1.0f, float minor_radius = 0.4f, int major_segments = 128, int minor_segments = 64);

// (p, q) torus knot: tube of radius `tube_radius` around the curve
// ((R + r cos(q t)) cos(p t), (R + r cos(q t)) sin(p t), r sin(q t)), R = 1, r = 0.4.
Mesh torus_knot(int p = 2, int q = 3, float tube_radius = 0.15f, int segments = 512, int tube_segments = 32);

// Utah teapot from Newell's 32 bicubic Bézier patches, tessellated `subdivisions` per patch
// side and welded; y up, base on y = 0.
Mesh teapot(int subdivisions = 16);

// A floor under `mesh`: a square of cells × cells quads (two triangles each, facing +y) in the
// plane of its lowest point, 2.5 times its larger horizontal extent wide and centred under it,
// for it to stand on and cast its shadows onto (`builtin:teapot:ground=N`).
void add_ground(Mesh& mesh, int cells);

// "sphere", "torus", "torus-knot", "teapot" -> mesh ("teapot:ground=N" with add_ground);
// throws InputError for an unknown name.
Mesh by_name(const std::string& name);
std::vector<std::string> names();

}  // namespace inkshade::builtin
