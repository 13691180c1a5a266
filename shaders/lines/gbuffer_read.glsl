// Reading the G-buffer (shaders/lines/gbuffer.frag), coordinates clamped to the image.
// Background pixels have id 0.
uniform sampler2D u_gbuffer_surface;
uniform sampler2D u_gbuffer_face_normal;
#define GBUFFER_FETCH(s, p) texelFetch(s, p, 0)
uniform ivec2 u_image_size;
uniform float u_far;  // linear depth given to the background

ivec2 clamp_pixel(ivec2 p) { return clamp(p, ivec2(0), u_image_size - 1); }

struct GSample {
    float ndotv;
    float depth;  // linear (view-space) depth; u_far on the background
    uint id;      // 0 = background
    vec2 w;       // view-space w.xy (image x right, y up), not normalised
};

GSample gbuffer_at(ivec2 p) {
    vec4 t = GBUFFER_FETCH(u_gbuffer_surface, clamp_pixel(p));
    GSample s;
    s.ndotv = t.x;
    s.id = floatBitsToUint(t.z);
    s.depth = s.id == 0u ? u_far : t.y;
    s.w = unpackHalf2x16(floatBitsToUint(t.w));
    return s;
}

vec3 face_normal_at(ivec2 p) { return GBUFFER_FETCH(u_gbuffer_face_normal, clamp_pixel(p)).xyz; }
