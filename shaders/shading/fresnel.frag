#version 450 core
// fresnel: rim glow ("Fresnel shading": brighter where the surface turns away from the viewer):
//   f = clamp(1 - |n.v|, 0, 1)^power,  rim = intensity * glow * f
//   mode "add":     C * (E * max(n.l, 0) + A) + rim
//   mode "replace": rim only, over black.
// A rim shader lights up inside out (a bright centre and a dark rim) where normals face away
// from the viewer: surface() flips n on back faces (open meshes, flipped windings), and |n.v|
// also covers meshes whose normals point inwards on front faces, so the rim is always at the
// silhouette and the centre of a view-facing surface is dark.
#include "common/surface.glsl"
uniform float u_power;
uniform float u_intensity;
uniform vec3 u_glow_color;
uniform int u_mode;  // 0 add, 1 replace

void shade() {
    Surface s = surface();
    float f = pow(clamp(1.0 - abs(dot(s.n, s.v)), 0.0, 1.0), u_power);
    vec3 rim = u_intensity * u_glow_color * f;
    vec3 base = (u_mode == 0) ? s.albedo * (u_light_color * lambert(s.n, s.l) + u_ambient) : vec3(0.0);
    o_color = encode_output(base + rim);
}
