// Vertex normals smoothed at several scales, for exaggerated shading (Rusinkiewicz, Burns &
// DeCarlo 2006, "Exaggerated Shading for Depicting Shape and Detail"): at scale σ each vertex
// gets the normalised Gaussian-weighted, area-weighted mean of the normals around it,
// n_σ(p) ∝ Σ_q A_q exp(−|p − q|² / 2σ²) n_q, distances measured in space (as the paper's
// implementation does) and cut off at 3σ.
#pragma once
#include <vector>

#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// Normals smoothed at scale `sigma` (world units), one per vertex. The sources are the vertices
// gathered into cubic cells of side σ/2 (each cell one source at the area-weighted centroid of
// its vertices, carrying their area-weighted normal sum), so every vertex reads a few hundred
// sources whatever σ: Gaussians σ/2 apart sum without ripple, and weighing a cell at its
// centroid widens the kernel by about 1 % (σ² + (σ/2)²/12 per axis). A vertex's area is a third of its faces'. Vertices
// without a source in reach (isolated, non-finite) or whose weighted sum vanishes keep their own normal; σ ≤ 0 returns
// `normals`. Deterministic (sources numbered in vertex order; vertices in parallel).
std::vector<glm::vec3> smoothed_normals(const Mesh& mesh, const std::vector<glm::vec3>& normals, float sigma);

// smoothed_normals at each of `sigmas`, finest first.
std::vector<std::vector<glm::vec3>> multiscale_normals(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                                       const std::vector<float>& sigmas);

}  // namespace inkshade::geometry
