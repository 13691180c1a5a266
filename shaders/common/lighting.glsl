// Conventions (docs/shading.md): n surface normal, l towards the light, v towards the
// viewer, r = reflect(-l, n), h = normalize(l + v). Values are written straight to the
// framebuffer, as hand-written GLSL shaders without a gamma step do (pixel =
// round(255 * clamp(formula))), unless u_srgb_output asks for the sRGB encode (the linear
// colour convention: --srgb, or mtoon's convention = threejs; render/color_convention.hpp).
uniform vec3 u_eye;            // camera position (world)
uniform vec3 u_view_dir;       // camera forward (world); used for orthographic views
uniform int u_orthographic;    // 1: v is -u_view_dir everywhere
uniform int u_light_type;      // 0 directional, 1 point, 2 spot (a point light with a cone)
uniform vec3 u_light_pos;
uniform vec3 u_light_target;   // spot: on the cone's axis
uniform vec3 u_light_color;    // E: the light's colour x intensity
uniform vec3 u_ambient;        // A
uniform vec3 u_base_color;     // multiplies the vertex/material colour: C = base * vertex
uniform int u_srgb_output;
uniform vec2 u_light_cone;     // spot (INKSHADE_SPOT_LIGHT): cos(outer angle), cos(inner angle)
uniform float u_light_range;   // INKSHADE_PHYSICAL_FALLOFF: zero light from this distance on (0: none)
uniform float u_light_falloff_decay;  // INKSHADE_PHYSICAL_FALLOFF: three.js PointLight.decay
// With INKSHADE_UNLIT (a mesh with glTF KHR_materials_unlit materials), per draw: the material
// is drawn as C without lighting, in the frame's output encoding (encode_output: sRGB in the
// linear convention, render/color_convention.hpp).
uniform int u_unlit;

vec3 to_light(vec3 p) {
    vec3 d = (u_light_type == 0) ? (u_light_pos - u_light_target) : (u_light_pos - p);
    return normalize(d);
}

vec3 to_viewer(vec3 p) {
    return (u_orthographic == 1) ? -normalize(u_view_dir) : normalize(u_eye - p);
}

float lambert(vec3 n, vec3 l) { return max(dot(n, l), 0.0); }

// A spot light (Light::cos_inner, cos_outer) and physical falloff (Light::physical_falloff)
// compile these in as program variants, so the other programs run as before (llvmpipe runs switched-off
// branches too).
#ifdef INKSHADE_SPOT_LIGHT
// three.js getSpotAttenuation: smoothstep(cos outer, cos inner, cos of the angle between the
// cone's axis and the direction to p).
float spot_attenuation(vec3 p) {
    float c = dot(normalize(p - u_light_pos), normalize(u_light_target - u_light_pos));
    float t = clamp((c - u_light_cone.x) / max(u_light_cone.y - u_light_cone.x, 1e-6), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}
#else
float spot_attenuation(vec3 p) { return 1.0; }
#endif

// What reaches p of the light colour: 1, or for a point or spot light in physical units
// (INKSHADE_PHYSICAL_FALLOFF) three.js's getDistanceAttenuation, 1 / max(d^decay, 0.01) windowed
// by (clamp(1 - (d / range)^4, 0, 1))^2, times the spot cone (getSpotAttenuation).
#ifdef INKSHADE_PHYSICAL_FALLOFF
float light_attenuation(vec3 p) {
    float d = length(u_light_pos - p);
    float falloff = 1.0 / max(pow(d, u_light_falloff_decay), 0.01);
    if (u_light_range > 0.0) {
        float x = d / u_light_range;
        float window = clamp(1.0 - x * x * x * x, 0.0, 1.0);
        falloff *= window * window;
    }
    return falloff * spot_attenuation(p);
}
#else
float light_attenuation(vec3 p) { return 1.0; }
#endif

// The unit normal n of the side the viewer sees (two-sided lighting, docs/shading.md): on a back
// face (front_facing = gl_FrontFacing false) turned towards the viewer v, unless it already
// faces v: a triangle wound against its neighbours, whose vertex normals follow the surface,
// is lit as the surface around it instead of as a dark speck.
vec3 seen_normal(vec3 n, vec3 v, bool front_facing) { return (!front_facing && dot(n, v) < 0.0) ? -n : n; }

vec3 srgb_encode(vec3 c) {
    vec3 lo = 12.92 * c;
    vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(hi, lo, lessThanEqual(c, vec3(0.0031308)));
}

vec4 encode_output(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return vec4(u_srgb_output == 1 ? srgb_encode(c) : c, 1.0);
}
