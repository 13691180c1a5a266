#version 450 core
// threejs-toon: three.js r187 MeshToonMaterial (lights_toon, gradientmap_pars_fragment):
//   u = 0.5 * n.l + 0.5 (n.l not clamped)
//   g = gradient-map[floor(N u)] (N texels, nearest filtering, clamped to the edge) when
//       use-gradient-map, else 0.7 below u = 0.7 and 1 above, blended over fwidth(u)/2 each side
//   out = sRGB(C/pi * (E * g + A) + emissive * emissive-intensity)   (no n.l factor)
#include "common/surface.glsl"
#include "common/threejs.glsl"
uniform vec3 u_color;     // linear (sRGB parameters are decoded on the CPU)
uniform vec3 u_emissive;
uniform float u_emissive_intensity;
uniform float u_gradient_map[32];
uniform int u_gradient_map_count;

float gradient_irradiance(float u) {
#if INKSHADE_USE_GRADIENT_MAP
    int i = clamp(int(floor(u * float(u_gradient_map_count))), 0, u_gradient_map_count - 1);
    return u_gradient_map[i];
#else
    float fw = 0.5 * fwidth(u);
    return mix(0.7, 1.0, smoothstep(0.7 - fw, 0.7 + fw, u));
#endif
}

void shade() {
    Surface s = surface();
    float g = gradient_irradiance(0.5 * dot(s.n, s.l) + 0.5);
    vec3 irradiance = threejs_direct_light(s.p) * g + threejs_ambient();
    vec3 c = irradiance * kThreejsReciprocalPi * (s.albedo * u_color) + u_emissive * u_emissive_intensity;
    o_color = threejs_output(c);
}
