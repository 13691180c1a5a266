// The fragment stage's main for every shading model and debug view: the model's shade()
// (declared here, defined in the model's own file after its includes) writes o_color, an unlit
// material's colour replaces it (u_unlit, common/lighting.glsl), then the surface line types
// the style turns on test the fragment (lines/surface_lines.glsl).
// Included by common/surface.glsl, so a model includes that one file and defines shade().
#include "lines/surface_lines.glsl"

void shade();

void main() {
    shade();
#ifdef INKSHADE_UNLIT
    if (u_unlit == 1) {
        vec3 c = clamp(surface().albedo, 0.0, 1.0);
        o_color = encode_output(c);
    }
#endif
#ifdef INKSHADE_RIM_CONTOUR
    o_color.rgb = rim_contour(o_color.rgb);
#endif
}
