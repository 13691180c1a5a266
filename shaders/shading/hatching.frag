#version 450 core
// hatching: the paper under the hatch strokes, which the renderer draws over it with the GPU
// strokes (the `hatch` line type: principal-direction streamlines drawn where the tone is dark,
// Hertzmann & Zorin 2000), washed with the Lambertian tone by `wash`:
//   out = C * mix(1, E * max(n.l, 0) + A, wash)
#include "common/surface.glsl"

uniform float u_wash;

void shade() {
    Surface s = surface();
    vec3 lit = u_light_color * lambert(s.n, s.l) + u_ambient;
    o_color = encode_output(s.albedo * mix(vec3(1.0), lit, u_wash));
}
