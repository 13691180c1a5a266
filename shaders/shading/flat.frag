#version 450 core
// flat: one normal per face from screen-space derivatives of the interpolated position,
// dFdx(p) x dFdy(p) (the triangle's plane), then Lambert: C * (E * max(n.l, 0) + A).
#include "common/surface.glsl"

void shade() {
    Surface s = surface();
    vec3 n = normalize(cross(dFdx(s.p), dFdy(s.p)));  // faces the viewer by construction
    o_color = encode_output(s.albedo * (u_light_color * lambert(n, s.l) + u_ambient));
}
