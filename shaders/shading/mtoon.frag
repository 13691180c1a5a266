#version 450 core
// mtoon: MToon 1.0, the VRM toon material (the VRM MToon 1.0 specification; the formula below is
// measured per channel from three-vrm's MToon 3.5.5 on three.js r187, in linear light):
//   t      = linearstep(-1 + toony, 1 - toony, clamp(n.l, -1, 1) + shift) * shadow
//   direct = E * k * mix(S, C, t)          (no n.l factor: the shade colour is lit too)
//   gi     = A * k * C
//   rim    = (rim-color * saturate(1 - n.v + lift)^power + matcap-color * matcap(n, v))
//            * rim-multiply(uv) * mix(1, (E + A) * k, rim-lighting-mix)
//   out    = clamp(direct + gi + rim)
// convention "threejs": k = 1/pi, the texture decoded from sRGB and the output sRGB-encoded
// (three-vrm on three.js: the renderer's linear colour convention sets u_srgb_output);
// convention "seeds" (Inkshade's default): k = 1, the texture and the value as they are, like
// the other shading models (unless --srgb).
// The rim's v in the threejs convention is normalize(eye - p) under every camera: three-vrm's
// mtoon.frag takes viewDir = normalize(vViewPosition), the point to the camera position, also
// for an orthographic camera (three.js's own materials use the view axis there, as
// common/lighting.glsl's to_viewer does, and so does the seeds convention).
// E carries the light's intensity and, for a point or spot light in the threejs convention,
// three.js's distance falloff and cone (light_attenuation; Light::physical_falloff).
// shadow = 1 (lit) .. 0 from the PCF-filtered shadow map when `shadows` is on; it scales t as
// the shading term of three-vrm does, so shadowed parts take the shade colour.
// INKSHADE_MTOON_TEXTURES: a VRM material's matcap and rim multiply textures (black and white
// when it has none, render/mtoon_textures.hpp); without them the matcap term is 0 and rim-multiply 1.
// INKSHADE_MTOON_OUTLINE: the outline draw (vertex stage: shading/mtoon_outline.glsl), shaded as
// three-vrm shades it: the same formula with the back face's normal negated (mtoon.frag's
// `normal *= -1.0` under OUTLINE), then out = outline-color * mix(1, direct + gi + rim,
// outline-lighting-mix).
#include "common/surface.glsl"
#include "common/shadow.glsl"

uniform vec3 u_shade_color;
uniform float u_shading_shift;
uniform float u_shading_toony;
uniform vec3 u_rim_color;
uniform float u_rim_fresnel_power;
uniform float u_rim_lift;
uniform float u_rim_lighting_mix;
uniform int u_convention;  // 0 seeds (as written), 1 threejs
uniform float u_shadow_softness;
uniform vec3 u_matcap_color;
uniform vec3 u_outline_color;
uniform float u_outline_lighting_mix;

#ifdef INKSHADE_MTOON_TEXTURES
uniform mat4 u_view;
uniform sampler2D u_matcap_texture;        // colour, black when the material has none
uniform sampler2D u_rim_multiply_texture;  // colour, white when the material has none

// three-vrm's matcap (mtoon.frag, USE_MATCAPTEXTURE): the normal in a view-space frame whose z
// is the direction to the viewer, x = normalize(v.z, 0, -v.x), y = v x x; the texture read
// where that frame puts it, row 0 (t = 0) for a normal pointing up, as three.js reads a glTF
// texture (flipY false).
vec3 matcap(vec3 n, vec3 v) {
    vec3 vd = normalize(mat3(u_view) * v), nv = mat3(u_view) * n;
    vec3 x = normalize(vec3(vd.z, 0.0, -vd.x));
    vec3 y = cross(vd, x);
    return texture(u_matcap_texture, 0.5 + 0.5 * vec2(dot(x, nv), -dot(y, nv))).rgb;
}
#endif

float linearstep(float a, float b, float x) { return clamp((x - a) / max(b - a, 1e-6), 0.0, 1.0); }

void shade() {
    Surface s = surface();
#ifdef INKSHADE_MTOON_OUTLINE
    s.n = -normalize(v_world_normal);
#endif
    const float kInvPi = 0.31830988618;
    float k = (u_convention == 1) ? kInvPi : 1.0;
    float ndotl = clamp(dot(s.n, s.l), -1.0, 1.0);
    float t = linearstep(-1.0 + u_shading_toony, 1.0 - u_shading_toony, ndotl + u_shading_shift);
    t *= shadow_visibility(s.p, s.n, s.l, u_shadow_softness);
    vec3 E = u_light_color * light_attenuation(s.p) * k, A = u_ambient * k;
    vec3 direct = E * mix(u_shade_color, s.albedo, t);
    vec3 gi = A * s.albedo;
    vec3 v = (u_convention == 1) ? normalize(u_eye - s.p) : s.v;
    float fresnel = pow(max(clamp(1.0 - dot(s.n, v) + u_rim_lift, 0.0, 1.0), 1e-6), u_rim_fresnel_power);
    vec3 rim = u_rim_color * fresnel;
#ifdef INKSHADE_MTOON_TEXTURES
    rim += u_matcap_color * matcap(s.n, v);
    rim *= texture(u_rim_multiply_texture, vec2(v_uv.x, 1.0 - v_uv.y)).rgb;
#endif
    rim *= mix(vec3(1.0), E + A, u_rim_lighting_mix);
    vec3 c = direct + gi + rim;
#ifdef INKSHADE_MTOON_OUTLINE
    c = u_outline_color * mix(vec3(1.0), c, u_outline_lighting_mix);
#endif
    c = clamp(c, 0.0, 1.0);
    o_color = encode_output(c);
}
