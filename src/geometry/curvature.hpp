// Per-vertex principal curvatures, principal directions and the curvature-derivative tensor,
// after Rusinkiewicz 2004, "Estimating Curvatures and Their Derivatives on Triangle Meshes"
// (the method of trimesh2's TriMesh_curvature.cc; implemented here from the paper).
//
// Sign convention: with outward normals a convex surface has positive curvature (a sphere of
// radius r gives k1 = k2 = 1/r).
#pragma once
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// No parameters yet: the estimator of Rusinkiewicz 2004 has none (the Voronoi/mixed-area
// weighting of Meyer et al. 2003 is fixed). Kept so that smoothing or weighting options can be
// added later without changing the signature.
struct CurvatureOptions {};

struct Curvature {
    // Unit principal directions; (pdir1, pdir2, normal) is a right-handed orthonormal frame.
    std::vector<glm::vec3> pdir1, pdir2;
    // Principal curvatures, k1 >= k2 (ordered by value, not magnitude as trimesh2 does).
    std::vector<float> k1, k2;
    // Curvature-derivative tensor C = ∇II (symmetric 2x2x2) in the (pdir1, pdir2) frame, its four
    // unique entries as trimesh2 stores them: x = C111 = ∂k1/∂s1, y = C112, z = C122,
    // w = C222 = ∂k2/∂s2 (s1, s2 arc length along pdir1, pdir2).
    std::vector<glm::vec4> dcurv;
    // Mixed Voronoi area of each vertex (Meyer et al. 2003); zero for isolated vertices.
    std::vector<float> point_area;
};

// Estimates curvature from the mesh and one (unit or not) normal per vertex. Degenerate faces
// (zero area, repeated or out-of-range indices) and faces touching a vertex whose normal is zero
// or not finite are skipped; vertices with no usable face get zero curvature and derivatives
// and an arbitrary tangent frame. Per-face work runs in parallel (TBB) and accumulation is in
// face order, so results do not depend on the thread count.
Curvature compute_curvature(const Mesh& mesh, const std::vector<glm::vec3>& vertex_normals,
                            const CurvatureOptions& options = {});

}  // namespace inkshade::geometry
