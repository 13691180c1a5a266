// The fragment stage's main for every shading model and debug view: the model's shade()
// (declared here, defined in the model's own file after its includes) writes o_color, an unlit
// material's colour replaces it (u_unlit, common/lighting.glsl), then the surface line types
// the style turns on test the fragment (lines/surface_lines.glsl), and a glTF material's alpha
// mode cuts it out or sets its coverage (INKSHADE_MATERIAL_ALPHA).
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
#ifdef INKSHADE_MATERIAL_ALPHA
    // three.js's alphatest_fragment: a MASK material keeps the fragment where alpha >= cutoff;
    // a BLEND one is written premultiplied (the colour target is, render/shading_pass.cpp blends
    // with ONE, ONE_MINUS_SRC_ALPHA: three.js's NormalBlending over the same pixels); OPAQUE and
    // MASK ones are opaque (glTF 2.0 section 3.9.4).
    float alpha = surface_alpha();
    if (u_alpha_mode == 1 && alpha < u_alpha_cutoff) discard;
    o_color = (u_alpha_mode == 2) ? vec4(o_color.rgb * alpha, alpha) : vec4(o_color.rgb, 1.0);
#endif
}
