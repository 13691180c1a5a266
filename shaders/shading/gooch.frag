#version 450 core
// gooch: cool-to-warm tone shading (Gooch, Gooch, Shirley, Cohen 1998, "A Non-Photorealistic
// Lighting Model for Automatic Technical Illustration"):
//   k_cool = k_blue + alpha * k_d,  k_blue = (0, 0, b)
//   k_warm = k_yellow + beta * k_d, k_yellow = (y, y, 0)
//   t = (1 + n.l) / 2
//   colour = t * k_warm + (1 - t) * k_cool        (warm faces the light)
//          + white * max(r.v, 0)^shininess where n.l > 0, when specular is on
// with k_d = C. Some course notes and blog posts print "t * k_cool - (1 - t) * k_warm" or
// "t * k_cool + (1 - t) * k_warm": the minus sign and the swapped colours are typos — the
// first goes negative, both put the cool colour on the lit side, against the paper's intent
// (warm colours on surfaces facing the light, cool ones on surfaces facing away).
#include "common/surface.glsl"

uniform float u_blue;
uniform float u_yellow;
uniform float u_alpha;
uniform float u_beta;
uniform int u_specular;
uniform float u_shininess;

void shade() {
    Surface s = surface();
    float ndotl = dot(s.n, s.l);
    vec3 k_cool = vec3(0.0, 0.0, u_blue) + u_alpha * s.albedo;
    vec3 k_warm = vec3(u_yellow, u_yellow, 0.0) + u_beta * s.albedo;
    float t = 0.5 * (1.0 + ndotl);
    vec3 c = t * k_warm + (1.0 - t) * k_cool;
    if (u_specular == 1 && ndotl > 0.0) c += vec3(pow(max(dot(reflect(-s.l, s.n), s.v), 0.0), u_shininess));
    o_color = encode_output(c);
}
