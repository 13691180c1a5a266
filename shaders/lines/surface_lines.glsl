// Surface line types: tests the shading pass makes per fragment after the model's shade()
// (common/shading_main.glsl), each compiled in by its #define (src/render/surface_lines.cpp).
//
// rim-contour (INKSHADE_RIM_CONTOUR): the fragment test |n.v| < t (t = `threshold`, 0.175 by
// default; docs/lines-raster.md), mixed over the shaded colour with coverage from the screen
// derivative of n.v (anti-aliased band edges, as fwidth does for cel bands). With
// INKSHADE_RIM_COMPENSATE = 1 the band is instead every pixel within `width` px of the
// n.v = 0 contour: constant width in pixels whatever the curvature. Near a fold contour n.v
// grows like the square root of the distance to it, so (n.v)^2 is the linear one:
// distance = (n.v)^2 / |grad (n.v)^2| = |n.v| / (2 |grad n.v|) (a Newton step).
// n is the interpolated normal turned towards the viewer on back faces (seen_normal, as
// common/surface.glsl).
// Where n does not vary across the pixel quad (a flat face of a mesh with hard edges) there is
// no contour inside the face to draw near: a plane's n.v never reaches 0 on it, and a band there
// would only be a flat face seen obliquely painted over (the contour is the face's edge, which
// the outline or the contour line type draws).
// Reads common/surface.glsl's v_world_pos and v_world_normal (it is included from there).
#include "common/lighting.glsl"

#ifdef INKSHADE_RIM_CONTOUR
uniform float u_rim_contour_threshold;
uniform vec3 u_rim_contour_color;
uniform float u_rim_contour_opacity;
uniform float u_rim_contour_width;  // pixels, compensated mode

// `shaded` with the rim line mixed over it.
vec3 rim_contour(vec3 shaded) {
    vec3 v = to_viewer(v_world_pos);
    vec3 n = seen_normal(normalize(v_world_normal), v, gl_FrontFacing);
    float ndotv = dot(n, v);
    float grad = max(length(vec2(dFdx(ndotv), dFdy(ndotv))), 1e-6);
    // Interpolating three equal normals varies them by rounding only (about 1e-7); curved
    // surfaces turn the normal by far more per pixel (2e-5 on a sphere 100000 px across).
    float bend = length(dFdx(n)) + length(dFdy(n));
    if (bend < 1e-5) return shaded;
#if INKSHADE_RIM_COMPENSATE
    float coverage = clamp(u_rim_contour_width - 0.5 * abs(ndotv) / grad + 0.5, 0.0, 1.0);
#else
    float coverage = clamp((u_rim_contour_threshold - abs(ndotv)) / grad + 0.5, 0.0, 1.0);
#endif
    return mix(shaded, u_rim_contour_color, u_rim_contour_opacity * coverage);
}
#endif
