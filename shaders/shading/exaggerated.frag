#version 450 core
// exaggerated: exaggerated shading (Rusinkiewicz, Burns & DeCarlo 2006, "Exaggerated Shading
// for Depicting Shape and Detail"), a local toon shading at several scales. With n_0 … n_b the
// normals smoothed at widths σ_0 < … < σ_b (b = INKSHADE_SCALES; doubling), per scale the light
// is turned to graze the next coarser surface, l_{i+1} = normalize(l − (l·n_{i+1}) n_{i+1}), so
// detail of every orientation is lit from the side:
//   c_i = clamp(a · n_i·l_{i+1}, −1, 1)      i < b
//   c_b = clamp(a · n_b·l, −1, 1)             the base coat: the overall shape, the real light
//   I   = 1/2 + 1/2 Σ_i k_i c_i,   k_i ∝ σ_i^(−detail) = 2^(−detail·i), Σ k_i = 1
//   colour = C · (E · I + A)
// Where the light is along n_{i+1} there is no grazing direction and c_i = 0.
#include "common/surface.glsl"

#ifndef INKSHADE_SCALES
#define INKSHADE_SCALES 6  // the `scales` parameter, defined by the program variant
#endif
// v_scale_normal[]: the declared `multiscale-normals` attribute, whose `in` the program variant
// generates (render/vertex_attributes/multiscale_normals.cpp); here only for this file compiled
// on its own.
#ifndef INKSHADE_MULTISCALE_NORMALS
in vec3 v_scale_normal[INKSHADE_SCALES + 1];
#endif

uniform float u_contrast;  // a
uniform float u_detail;    // k_i ∝ σ_i^(−detail)

void shade() {
    Surface s = surface();
    // The side the viewer sees: every scale's normal turned as s.n was.
    float side = dot(s.n, v_world_normal) < 0.0 ? -1.0 : 1.0;
    vec3 n[INKSHADE_SCALES + 1];
    for (int i = 0; i <= INKSHADE_SCALES; ++i) n[i] = side * normalize(v_scale_normal[i]);
    float sum = 0.0, total = 0.0;
    for (int i = 0; i <= INKSHADE_SCALES; ++i) {
        float k = exp2(-u_detail * float(i));
        float c;
        if (i < INKSHADE_SCALES) {
            vec3 grazing = s.l - dot(s.l, n[i + 1]) * n[i + 1];
            float len = length(grazing);
            c = len > 1e-6 ? clamp(u_contrast * dot(n[i], grazing / len), -1.0, 1.0) : 0.0;
        } else {
            c = clamp(u_contrast * dot(n[i], s.l), -1.0, 1.0);
        }
        sum += k * c;
        total += k;
    }
    float intensity = 0.5 + 0.5 * sum / total;
    o_color = encode_output(s.albedo * (u_light_color * intensity + u_ambient));
}
