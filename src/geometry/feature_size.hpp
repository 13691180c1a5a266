// The length that makes the thresholds of the curvature-based lines (suggestive contours,
// ridges, valleys) dimensionless when the user gives none: rtsc's estimator, from the mesh's
// curvature rather than its size, so a gently curved part and a noisy scan of the same extent
// get thresholds that suit them.
#pragma once
#include "geometry/curvature.hpp"
#include "inkshade/mesh.hpp"

namespace inkshade::geometry {

// A sphere around every vertex (Ritter 1990, "An efficient bounding sphere"): within a few
// percent of the smallest one, in two passes. Radius 0 at the origin for no vertex; non-finite
// vertices are skipped.
struct BoundingSphere {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};
BoundingSphere bounding_sphere(const Mesh& mesh);
inline float bounding_sphere_radius(const Mesh& mesh) { return bounding_sphere(mesh).radius; }

// rtsc 1.6's feature size (compute_feature_size): 1 % of the reciprocal of the 10th percentile
// of |k1| and |k2| over a sample of 500 vertices (its linear congruential generator, so the same
// vertices every run), at most 5 % of the bounding sphere's radius — a flat part, where the
// percentile is 0, gets that cap. 1 for a mesh without extent.
float line_feature_size(const Mesh& mesh, const Curvature& curvature);

}  // namespace inkshade::geometry
