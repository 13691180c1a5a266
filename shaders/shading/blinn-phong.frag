#version 450 core
// blinn-phong: as phong with the half vector h = normalize(l + v) (Blinn 1977):
//   C * (A + E * max(n.l, 0)) + k_s * E * max(n.h, 0)^shininess, specular only where n.l > 0.
#include "common/surface.glsl"
uniform float u_shininess;
uniform vec3 u_specular;

void shade() {
    Surface s = surface();
    float ndotl = dot(s.n, s.l);
    vec3 h = normalize(s.l + s.v);
    float spec = ndotl > 0.0 ? pow(max(dot(s.n, h), 0.0), u_shininess) : 0.0;
    vec3 c = s.albedo * (u_ambient + u_light_color * max(ndotl, 0.0)) + u_specular * u_light_color * spec;
    o_color = encode_output(c);
}
