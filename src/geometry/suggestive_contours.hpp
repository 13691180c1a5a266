// Object-space suggestive contours (line type `suggestive`; `suggestive-image` is the image-space
// method): zero crossings of the radial curvature κr where its derivative along the projected
// view vector is positive, after DeCarlo, Finkelstein, Rusinkiewicz & Santella 2003,
// "Suggestive Contours for Conveying Shape", with the derivative, trimming and fading of
// DeCarlo, Finkelstein & Rusinkiewicz 2004, "Interactive Rendering of Suggestive Contours with
// Temporal Coherence" (as rtsc does them).
#pragma once
#include <vector>

#include "geometry/contours.hpp"
#include "geometry/curvature.hpp"
#include "geometry/feature_size.hpp"

namespace inkshade::geometry {

struct SuggestiveOptions {
    // Trim: a point is kept where D_w κr / (n·v) > threshold / feature_size² (dimensionless;
    // rtsc's sug_thresh default 0.01). Removes the weak, noise-born zeros of κr (DeCarlo 2003 §4).
    float threshold = 0.01f;
    // Fade: strength = x / (x + fade / feature_size²), x = D_w κr / (n·v) − threshold /
    // feature_size², so lines fade in from the trim point (rtsc's draw_faded constant 0.03);
    // 0 turns fading off (strength 1).
    float fade = 0.03f;
    // The length (world units) that makes the two values above dimensionless; 0 = rtsc's
    // automatic one from the curvature (feature_size.hpp).
    float feature_size = 0.0f;
    // Suggestive highlights instead (line type `suggestive-highlight`; DeCarlo & Rusinkiewicz
    // 2007, "Highlight Lines for Conveying Shape"): the zeros of κr where D_w κr < 0, trimmed
    // where −D_w κr / (n·v) > threshold / feature_size² (rtsc's sh_thresh default 0.02) and
    // faded alike.
    bool highlights = false;
};

// Per-vertex view-dependent curvature for one view (a debug view shows kr).
struct RadialCurvature {
    // κr = k1 cos²φ + k2 sin²φ, φ the angle from pdir1 to w, the view vector projected onto the
    // tangent plane (1/world length); 0 where w vanishes (view along the normal).
    std::vector<float> kr;
    // D_w κr with |w| = sin θ, θ the angle between n and v (1/world length²): the cubic form of
    // the derivative tensor plus the 2 K cot θ term at κr = 0 (DeCarlo 2004 §3, written as
    // −2 (n·v) τr² with τr the geodesic torsion along w, as rtsc does).
    std::vector<float> dw_kr;
    std::vector<float> ndotv;  // n·v, as view_dot_normal
};

// κr and D_w κr per vertex. `normals` must be the normals `curvature` was computed with; throws
// std::invalid_argument when sizes differ from the vertex count.
RadialCurvature radial_curvature(const Mesh& mesh, const std::vector<glm::vec3>& normals, const Curvature& curvature,
                                 const Camera& camera);

// Suggestive contour segments in face order (parallel over faces, deterministic). The zero set
// of κr sin²θ (same zeros as κr, defined everywhere) is interpolated on edges exactly as
// extract_contours does for n·v, so neighbouring faces share bit-identical points, node keys
// and strengths. Each segment is then cut to where it is front-facing (n·v > 0) and passes the
// threshold, with D_w κr and n·v interpolated linearly along it (rtsc's sctest_num /
// sctest_den; with options.highlights the sign of D_w κr turned, rtsc's shtest_num); a cut end
// gets face_interior_key and strength 0 (or 1 where it meets a contour). Walking a → b keeps
// κr ≥ 0 on the left.
std::vector<LineSegment> extract_suggestive_contours(const Mesh& mesh, const std::vector<glm::vec3>& normals,
                                                     const Curvature& curvature, const Camera& camera,
                                                     const SuggestiveOptions& options = {});

}  // namespace inkshade::geometry
