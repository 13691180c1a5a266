// Conventions (docs/shading.md): n surface normal, l towards the light, v towards the
// viewer, r = reflect(-l, n), h = normalize(l + v). Values are written straight to the
// framebuffer, as hand-written GLSL shaders without a gamma step do (pixel =
// round(255 * clamp(formula))), unless u_srgb_output asks for the sRGB encode.
uniform vec3 u_eye;            // camera position (world)
uniform vec3 u_view_dir;       // camera forward (world); used for orthographic views
uniform int u_orthographic;    // 1: v is -u_view_dir everywhere
uniform int u_light_type;      // 0 directional, 1 point
uniform vec3 u_light_pos;
uniform vec3 u_light_target;
uniform vec3 u_light_color;    // E
uniform vec3 u_ambient;        // A
uniform vec3 u_base_color;     // multiplies the vertex/material colour: C = base * vertex
uniform int u_srgb_output;

vec3 to_light(vec3 p) {
    vec3 d = (u_light_type == 0) ? (u_light_pos - u_light_target) : (u_light_pos - p);
    return normalize(d);
}

vec3 to_viewer(vec3 p) {
    return (u_orthographic == 1) ? -normalize(u_view_dir) : normalize(u_eye - p);
}

float lambert(vec3 n, vec3 l) { return max(dot(n, l), 0.0); }

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
