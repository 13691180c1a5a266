#version 450 core
// phong: ambient + diffuse + specular (Phong 1975, "Illumination for Computer Generated Pictures"):
//   C * (A + E * max(n.l, 0)) + k_s * E * max(r.v, 0)^shininess, specular only where n.l > 0,
//   r = reflect(-l, n).
#include "common/surface.glsl"
uniform float u_shininess;
uniform vec3 u_specular;

void shade() {
    Surface s = surface();
    float ndotl = dot(s.n, s.l);
    vec3 r = reflect(-s.l, s.n);
    float spec = ndotl > 0.0 ? pow(max(dot(r, s.v), 0.0), u_shininess) : 0.0;
    vec3 c = s.albedo * (u_ambient + u_light_color * max(ndotl, 0.0)) + u_specular * u_light_color * spec;
    o_color = encode_output(c);
}
