#version 450 core
// threejs-lambert: three.js r187 MeshLambertMaterial (lights_lambert: RE_Direct_Lambert and
// RE_IndirectDiffuse_Lambert with BRDF_Lambert = diffuse / pi), per pixel:
//   sRGB(C/pi * (E * max(n.l, 0) + A) + emissive * emissive-intensity)
#include "common/surface.glsl"
#include "common/threejs.glsl"
uniform vec3 u_color;     // linear (sRGB parameters are decoded on the CPU)
uniform vec3 u_emissive;
uniform float u_emissive_intensity;

void shade() {
    Surface s = surface();
    vec3 irradiance = threejs_direct_light(s.p) * max(dot(s.n, s.l), 0.0) + threejs_ambient();
    vec3 c = irradiance * kThreejsReciprocalPi * (s.albedo * u_color) + u_emissive * u_emissive_intensity;
    o_color = threejs_output(c);
}
