// Principal highlights (line type `principal-highlight`; DeCarlo & Rusinkiewicz 2007,
// "Highlight Lines for Conveying Shape"): where the view vector is perpendicular to the
// principal direction e1 of larger curvature magnitude, so that n·v has a maximum along e1 —
// the line a glossy cylinder's highlight runs along — kept where that maximum is strong. As
// rtsc 1.6 draws them (draw_mesh_ph): zero crossings of v·e1 where (k1² − k2²)(n·v), k1 the
// larger-magnitude curvature, exceeds a threshold, faded in above it.
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "geometry/curvature.hpp"
#include "inkshade/camera.hpp"

namespace inkshade::geometry {

struct PrincipalHighlightOptions {
    // Keep a crossing where (k1² − k2²)(n·v) > threshold / feature_size² (dimensionless; rtsc's
    // ph_thresh default 0.04).
    float threshold = 0.04f;
    // Strength x / (x + t) with x = (k1² − k2²)(n·v) − t, t the threshold above: rising from 0
    // at the trim point (rtsc's draw_faded, on by default); off: strength 1.
    bool fade = true;
    // Where k1 > 0 (the surface bends away from the viewer along e1: a bump, a cylinder seen
    // from outside; rtsc's "Principal Hlt. (R)") and where k1 < 0 (a groove; "(V)").
    bool convex = true;
    bool concave = true;
    // World units; 0 = line_feature_size(mesh, curvature) (feature_size.hpp).
    float feature_size = 0.0f;
};

// Principal-highlight segments in face order (parallel over faces, deterministic). e1 is a line
// field (no sign), so each edge turns its far end's e1 to agree with its lower index's and
// decides its crossing, position and strength from that edge alone: neighbouring faces share
// bit-identical points and edge keys. A face draws when its three e1 lie within 45° of the one
// with the largest |k1| (rtsc's test; the field turns near umbilics and where |k1| = |k2|), k1
// has one sign at its three vertices (and that kind is asked for), and exactly two of its
// edges cross. `normals` must be the ones the curvature was computed with; throws
// std::invalid_argument when sizes differ from the vertex count.
std::vector<LineSegment> extract_principal_highlights(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                                      const Curvature& curvature, const Camera& camera,
                                                      const PrincipalHighlightOptions& options = {});

}  // namespace inkshade::geometry
