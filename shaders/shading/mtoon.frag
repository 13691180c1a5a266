#version 450 core
// mtoon: MToon 1.0, the VRM toon material (the VRM MToon 1.0 specification; the formula below is
// measured per channel from three-vrm's MToon 3.5.5 on three.js r187, in linear light):
//   shift  = shading-shift + shading-shift-texture(uv).r * shading-shift-texture-scale
//   t      = linearstep(-1 + toony, 1 - toony, clamp(n.l, -1, 1) + shift) * shadow
//   S      = shade-color * shade-multiply-texture(uv)
//   direct = E * k * mix(S, C, t)          (no n.l factor: the shade colour is lit too)
//   gi     = A * k * C
//   rim    = (rim-color * saturate(1 - n.v + lift)^power + matcap-color * matcap(n, v))
//            * rim-multiply(uv) * mix(1, (E + A) * k, rim-lighting-mix)
//   emit   = emissive * emissive-intensity * emissive-texture(uv)
//   out    = clamp(direct + gi + rim + emit)
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
// INKSHADE_MTOON_TEXTURES: a VRM material's textures (render/mtoon_textures.hpp), each reading
// as nothing when the material has none: matcap and shading shift black, the multiplying ones
// white, the normal map off (u_normal_texture_on 0).
// uv is the mesh's uvs moved by the UV animation at u_time seconds (three-vrm's mtoon.frag, its
// offsets accumulated by MToonMaterial.update as speed x time), read by every texture but the
// matcap (which reads at the normal) and the mask itself:
//   mask = uv-animation-mask-texture(uv0).b                          (1 without one)
//   uv'  = uv0 + (scroll-x-speed, scroll-y-speed) * time * mask
//   a    = rotation-speed * time * mask                               (radians)
//   uv   = 0.5 + (cos a * d.s + sin a * d.t, -sin a * d.s + cos a * d.t),  d = uv' - 0.5
// n is perturbed by the normal map as three.js r151+ does for a mesh without tangents
// (getTangentFrame: a cotangent frame from the screen-space derivatives of the position and uv,
// after Schueler 2006, "Normal Mapping without Precomputed Tangents", ShaderX5), with GLTFLoader's
// normalScale (scale, -scale) for such a mesh, which turns the frame's t-down bitangent into
// glTF's up-the-image one: n = normalize(T * x * scale - B * y * scale + N * z), (x, y, z) the
// texel * 2 - 1. The shadow's bias keeps the geometric normal.
// INKSHADE_MTOON_OUTLINE: the outline draw (vertex stage: shading/mtoon_outline.glsl), shaded as
// three-vrm shades it: the same formula with the outward normal (three.js negates a BackSide
// material's normal, mtoon.frag's `normal *= -1.0` under OUTLINE turns it back; a normal map
// replaces it, on the inward frame), then
// out = outline-color * mix(1, direct + gi + rim + emit, outline-lighting-mix).
#define INKSHADE_TEXTURE_UV 1  // texture_uv() below: the UV animation
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
uniform float u_shading_shift_texture_scale;
uniform vec3 u_emissive;
uniform float u_emissive_intensity;
uniform float u_normal_scale;
uniform float u_uv_animation_scroll_x_speed;
uniform float u_uv_animation_scroll_y_speed;
uniform float u_uv_animation_rotation_speed;
uniform float u_time;  // seconds (RenderOptions::time)

#ifdef INKSHADE_MTOON_TEXTURES
uniform mat4 u_view;
uniform sampler2D u_matcap_texture;               // colour, black when the material has none
uniform sampler2D u_rim_multiply_texture;         // colour, white when the material has none
uniform sampler2D u_shade_multiply_texture;       // colour, white
uniform sampler2D u_shading_shift_texture;        // colour as three-vrm marks it (sRGB), black
uniform sampler2D u_emissive_texture;             // colour, white
uniform sampler2D u_normal_texture;               // data; read only when u_normal_texture_on
uniform sampler2D u_uv_animation_mask_texture;    // data (blue channel), white
uniform int u_normal_texture_on;                  // per draw: the material has a normal map
// Per draw, each texture's KHR_texture_transform (three-vrm's *UvTransform uniforms; identity
// unless the material has one), applied to the animated uv (the mask's to the uv before the
// animation, the matcap's to its view-space coordinate).
uniform mat3 u_matcap_texture_uv_transform = mat3(1.0);
uniform mat3 u_rim_multiply_texture_uv_transform = mat3(1.0);
uniform mat3 u_shade_multiply_texture_uv_transform = mat3(1.0);
uniform mat3 u_shading_shift_texture_uv_transform = mat3(1.0);
uniform mat3 u_emissive_texture_uv_transform = mat3(1.0);
uniform mat3 u_normal_texture_uv_transform = mat3(1.0);
uniform mat3 u_uv_animation_mask_texture_uv_transform = mat3(1.0);
vec2 transformed(mat3 t, vec2 uv) { return (t * vec3(uv, 1.0)).xy; }

// three-vrm's matcap (mtoon.frag, USE_MATCAPTEXTURE): the normal in a view-space frame whose z
// is the direction to the viewer, x = normalize(v.z, 0, -v.x), y = v x x; the texture read
// where that frame puts it, row 0 (t = 0) for a normal pointing up, as three.js reads a glTF
// texture (flipY false).
vec3 matcap(vec3 n, vec3 v) {
    vec3 vd = normalize(mat3(u_view) * v), nv = mat3(u_view) * n;
    vec3 x = normalize(vec3(vd.z, 0.0, -vd.x));
    vec3 y = cross(vd, x);
    return texture(u_matcap_texture, transformed(u_matcap_texture_uv_transform, 0.5 + 0.5 * vec2(dot(x, nv), -dot(y, nv)))).rgb;
}

// three.js's getTangentFrame (normal_fragment_begin without a tangent attribute) in world space
// (the view is a rigid motion, so the frame is the view-space one turned back), its tangent and
// bitangent turned with the face as three.js does for a DoubleSide material (`face` -1 on a side
// whose normal was negated), then the normal map's texel in it.
vec3 normal_mapped(vec3 n, float face, vec3 p, vec2 uv) {
    vec3 q0 = dFdx(p), q1 = dFdy(p);
    vec2 st0 = dFdx(uv), st1 = dFdy(uv);
    vec3 q1perp = cross(q1, n), q0perp = cross(n, q0);
    vec3 t = q1perp * st0.x + q0perp * st1.x;
    vec3 b = q1perp * st0.y + q0perp * st1.y;
    float det = max(dot(t, t), dot(b, b));
    float scale = det == 0.0 ? 0.0 : face * inversesqrt(det);
    vec3 m = texture(u_normal_texture, uv).xyz * 2.0 - 1.0;
    m.xy *= vec2(u_normal_scale, -u_normal_scale);
    return normalize(mat3(t * scale, b * scale, n) * m);
}
#endif

#if defined(INKSHADE_BASE_TEXTURE) || defined(INKSHADE_MTOON_TEXTURES)
// three-vrm's UV animation (mtoon.frag's main), its offsets and phase speed x time.
vec2 texture_uv() {
    vec2 uv = vec2(v_uv.x, 1.0 - v_uv.y);
    float mask = 1.0;
#ifdef INKSHADE_MTOON_TEXTURES
    mask = texture(u_uv_animation_mask_texture, transformed(u_uv_animation_mask_texture_uv_transform, uv)).b;
#endif
    uv += vec2(u_uv_animation_scroll_x_speed, u_uv_animation_scroll_y_speed) * (u_time * mask);
    float phase = u_uv_animation_rotation_speed * u_time * mask;
    float c = cos(phase), s = sin(phase);
    return mat2(c, -s, s, c) * (uv - 0.5) + 0.5;
}
#endif

float linearstep(float a, float b, float x) { return clamp((x - a) / max(b - a, 1e-6), 0.0, 1.0); }

void shade() {
    Surface s = surface();
    // The normal the tangent frame is built on, and the one shaded. The outline material is
    // BackSide, so three.js's vertex stage negates its normal (FLIP_SIDED); three-vrm's
    // `normal *= -1.0` turns it back: the outline is lit with the outward normal, while a normal
    // map's frame is built on the inward one (normal_fragment_maps comes after the negation).
    vec3 raw = normalize(v_world_normal);
#ifdef INKSHADE_MTOON_OUTLINE
    vec3 frame_n = -raw;
    float face = 1.0;  // BackSide, not DoubleSide: the frame is not turned
    s.n = raw;
#else
    vec3 frame_n = s.n;
    float face = dot(frame_n, raw) < 0.0 ? -1.0 : 1.0;  // a DoubleSide back face's frame turns
#endif
    vec3 geometric_n = s.n;
    vec3 shade_color = u_shade_color;
    float shift = u_shading_shift;
    vec3 emissive = u_emissive * u_emissive_intensity;
#ifdef INKSHADE_MTOON_TEXTURES
    vec2 uv = texture_uv();
    // three-vrm's normal map replaces the normal, the outline's negated one too.
    if (u_normal_texture_on == 1)
        s.n = normal_mapped(frame_n, face, s.p,
                            transformed(u_normal_texture_uv_transform, uv));
    shade_color *= texture(u_shade_multiply_texture, transformed(u_shade_multiply_texture_uv_transform, uv)).rgb;
    shift += texture(u_shading_shift_texture, transformed(u_shading_shift_texture_uv_transform, uv)).r *
             u_shading_shift_texture_scale;
    emissive *= texture(u_emissive_texture, transformed(u_emissive_texture_uv_transform, uv)).rgb;
#endif
    const float kInvPi = 0.31830988618;
    float k = (u_convention == 1) ? kInvPi : 1.0;
    float ndotl = clamp(dot(s.n, s.l), -1.0, 1.0);
    float t = linearstep(-1.0 + u_shading_toony, 1.0 - u_shading_toony, ndotl + shift);
    t *= shadow_visibility(s.p, geometric_n, s.l, u_shadow_softness);
    vec3 E = u_light_color * light_attenuation(s.p) * k, A = u_ambient * k;
    vec3 direct = E * mix(shade_color, s.albedo, t);
    vec3 gi = A * s.albedo;
    vec3 v = (u_convention == 1) ? normalize(u_eye - s.p) : s.v;
    float fresnel = pow(max(clamp(1.0 - dot(s.n, v) + u_rim_lift, 0.0, 1.0), 1e-6), u_rim_fresnel_power);
    vec3 rim = u_rim_color * fresnel;
#ifdef INKSHADE_MTOON_TEXTURES
    rim += u_matcap_color * matcap(s.n, v);
    rim *= texture(u_rim_multiply_texture, transformed(u_rim_multiply_texture_uv_transform, uv)).rgb;
#endif
    rim *= mix(vec3(1.0), E + A, u_rim_lighting_mix);
    vec3 c = direct + gi + rim + emissive;
#ifdef INKSHADE_MTOON_OUTLINE
    c = u_outline_color * mix(vec3(1.0), c, u_outline_lighting_mix);
#endif
    c = clamp(c, 0.0, 1.0);
    o_color = encode_output(c);
}
