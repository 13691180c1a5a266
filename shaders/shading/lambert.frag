#version 450 core
// lambert: per-pixel Lambert with interpolated (Phong) normals, C * (E * max(n.l, 0) + A)
// (Lambert's cosine law: diffuse light proportional to max(n.l, 0)).
#include "common/surface.glsl"

void shade() {
    Surface s = surface();
    o_color = encode_output(s.albedo * (u_light_color * lambert(s.n, s.l) + u_ambient));
}
