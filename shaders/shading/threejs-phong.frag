#version 450 core
// threejs-phong: three.js r187 MeshPhongMaterial (lights_phong: RE_Direct_BlinnPhong), per pixel
// with irradiance I = E * max(n.l, 0):
//   diffuse  = C/pi * (I + A)
//   specular = I * F * (s + 2)/(8 pi) * max(n.h, 0)^s      (BRDF_BlinnPhong: G = 1/4, D = (s/2 + 1)/pi * ...)
//   F        = S + (1 - S) * 2^((-5.55473 v.h - 6.98316) v.h)  (F_Schlick, Epic's exp2 form)
//   out      = sRGB(diffuse + specular + emissive * emissive-intensity)
#include "common/surface.glsl"
#include "common/threejs.glsl"
uniform vec3 u_color;     // linear (sRGB parameters are decoded on the CPU)
uniform vec3 u_specular;
uniform float u_shininess;
uniform vec3 u_emissive;
uniform float u_emissive_intensity;

void shade() {
    Surface s = surface();
    vec3 irradiance = threejs_direct_light(s.p) * max(dot(s.n, s.l), 0.0);
    vec3 h = normalize(s.l + s.v);
    float ndoth = max(dot(s.n, h), 0.0), vdoth = max(dot(s.v, h), 0.0);
    float fresnel = exp2((-5.55473 * vdoth - 6.98316) * vdoth);
    vec3 F = u_specular * (1.0 - fresnel) + vec3(fresnel);
    float shininess = max(u_shininess, 1e-4);  // three.js uploads max(shininess, 1e-4): no pow(0, 0)
    float D = kThreejsReciprocalPi * (0.5 * shininess + 1.0) * pow(ndoth, shininess);
    vec3 specular = irradiance * F * (0.25 * D);
    vec3 diffuse = (irradiance + threejs_ambient()) * kThreejsReciprocalPi * (s.albedo * u_color);
    o_color = threejs_output(diffuse + specular + u_emissive * u_emissive_intensity);
}
