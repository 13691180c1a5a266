// Apparent ridges (line type `apparent-ridge`): lines where the surface normal turns fastest
// per unit of distance in the image, after Judd, Durand & Adelson 2007, "Apparent Ridges for
// Line Drawing" (thresholds, the derivative estimate and fading as rtsc 1.6 draws them).
//
// The view-dependent curvature: the normal n as a function of the image position x has the
// derivative Q = S P⁻¹, S the shape operator and P the projection of the tangent plane onto the
// image plane (it shortens the projected view direction w by cos θ = n·v). Its largest singular
// value q1 is the maximum view-dependent curvature, reached along the image direction t1; an
// apparent ridge is where q1 has a maximum along t1 (D_t1 q1 = 0, decreasing on both sides).
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "geometry/curvature.hpp"

namespace inkshade::geometry {

struct ApparentRidgeOptions {
    // Keep points where q1² > threshold / feature_size² (dimensionless; rtsc's ar_thresh 0.1,
    // which its code compares with the squared curvature, the eigenvalue of QᵀQ).
    float threshold = 0.1f;
    // World units; 0 = line_feature_size(mesh, curvature) (feature_size.hpp).
    float feature_size = 0.0f;
};

// Per-vertex view-dependent curvature of one view.
struct ViewDependentCurvature {
    std::vector<float> q1;      // maximum view-dependent curvature (1/world length)
    std::vector<glm::vec3> t1;  // unit tangent direction whose image is the direction of q1
    // Unit image-plane direction of t1 (world vector perpendicular to the view vector); the
    // derivative below is per unit of distance along it.
    std::vector<glm::vec3> screen_t1;
    // D_t1 q1 (1/world length²), estimated as rtsc does: q1 interpolated where the line through
    // the vertex along t1 leaves each of its faces, divided by the image-plane distance there,
    // averaged over the faces that have such a point.
    std::vector<float> dt1_q1;
};

// q1, t1 and D_t1 q1 per vertex (cos θ is taken as |n·v|, at least 1e-4, so the far side of a
// contour mirrors the near side). `normals` must be those `curvature` was computed with; throws
// std::invalid_argument when sizes differ from the vertex count.
ViewDependentCurvature view_dependent_curvature(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                                const Curvature& curvature, const Camera& camera);

// Apparent-ridge segments in face order (parallel over faces, deterministic). On each edge the
// vector field D_t1 q1 · t1 (pointing up the slope of q1, whatever the sign of t1) is followed:
// where it turns round between the two ends the crossing is placed by |D_t1 q1| and decided from
// the edge alone, so neighbouring faces share bit-identical points and keys. A face with two
// such edges gives a segment when the field at its three corners points towards the segment (a
// maximum, not a minimum; rtsc's test); one with three gives none. The segment is cut to where
// q1² (interpolated linearly) passes the threshold; a cut end gets face_interior_key and
// strength 0, else strength = 1 − threshold / q1² (rtsc's fade).
std::vector<LineSegment> extract_apparent_ridges(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                                 const Curvature& curvature, const Camera& camera,
                                                 const ApparentRidgeOptions& options = {});

}  // namespace inkshade::geometry
