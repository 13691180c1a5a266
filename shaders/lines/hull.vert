#version 450 core
// hull: inverted hull (the classic inverted hull; Qu, Chen & Zwicker 2022, section 3.6): p' = p + alpha * n with
// n the welded (position-averaged) normal, so split normals at creases do not crack the hull.
//   world mode:  alpha = world-width (world units, Qu et al. 2022's offset)
//   screen mode: the vertex moves width pixels in the image along the projected normal
//                direction d(proj(p + t n))/dt at t = 0, whatever the distance and resolution.
layout(location = 0) in vec3 a_position;
layout(location = 3) in vec3 a_hull_normal;

uniform mat4 u_view_proj;
uniform int u_world_mode;
uniform float u_world_width;
uniform float u_width_px;
uniform vec2 u_viewport_size;
#include "common/back_face_push.glsl"

void main() {
    vec3 n = a_hull_normal;
    if (u_world_mode == 1) {
        gl_Position = pushed_back(u_view_proj * vec4(a_position + u_world_width * n, 1.0));
        return;
    }
    vec4 clip = u_view_proj * vec4(a_position, 1.0);
    vec4 clip_n = u_view_proj * vec4(n, 0.0);
    // Derivative of the NDC position along n, in pixels.
    vec2 d_ndc = (clip_n.xy * clip.w - clip.xy * clip_n.w) / (clip.w * clip.w);
    vec2 d_px = d_ndc * 0.5 * u_viewport_size;
    float len = length(d_px);
    if (len > 1e-12) clip.xy += (d_px / len) * u_width_px * 2.0 / u_viewport_size * clip.w;
    gl_Position = pushed_back(clip);
}
