#version 450 core
// Debug view `kr`: the radial curvature kr per vertex for this view (CPU, Rusinkiewicz 2004
// curvatures; DeCarlo et al. 2003 section 3), made dimensionless with the feature size 1% of the
// bounding-box diagonal (the unit of the suggestive threshold, docs/lines.md) and mapped to a
// diverging scale: red convex along w, white kr = 0 (suggestive contour candidates), blue
// concave.
#include "common/surface.glsl"  // outputs, bounding box
// v_kr: the declared `radial-curvature` attribute, whose `in` the program variant generates;
// here only for this file compiled on its own.
#ifndef INKSHADE_RADIAL_CURVATURE
in float v_kr;
#endif
uniform float u_range;
void shade() {
    float feature = 0.01 * length(u_bbox_max - u_bbox_min);
    float t = clamp(v_kr * feature / u_range, -1.0, 1.0);
    vec3 c = t >= 0.0 ? mix(vec3(1.0), vec3(0.85, 0.1, 0.05), t) : mix(vec3(1.0), vec3(0.05, 0.25, 0.85), -t);
    o_color = vec4(c, 1.0);
}
