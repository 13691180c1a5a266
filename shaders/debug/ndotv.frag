#version 450 core
// Debug view `ndotv`: grey level n.v (1 facing the viewer, 0 at the contour, where n.v = 0).
#include "common/surface.glsl"
void shade() {
    Surface s = surface();
    o_color = vec4(vec3(clamp(dot(s.n, s.v), 0.0, 1.0)), 1.0);
}
