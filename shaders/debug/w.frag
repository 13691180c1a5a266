#version 450 core
// Debug view `w`: v projected onto the tangent plane, w = v - (n.v) n (DeCarlo et al. 2003),
// encoded as 0.5 * w + 0.5 (|w| <= 1, zero where the surface faces the viewer).
#include "common/surface.glsl"
void shade() {
    Surface s = surface();
    vec3 w = s.v - dot(s.n, s.v) * s.n;
    o_color = vec4(0.5 * w + 0.5, 1.0);
}
