#version 450 core
// stroke: one instance per polyline segment; the 4 vertices of a quad enclosing the capsule
// of the segment (radius r0 at the start, r1 at the end) plus one pixel for anti-aliasing.
// Coordinates are image pixels, origin top-left, y down (LinePath's convention).
layout(location = 0) in vec4 a_ends;          // x0, y0, x1, y1
layout(location = 1) in vec4 a_radius_depth;  // r0, r1, d0, d1
layout(location = 2) in vec4 a_color0;        // colour at the start; w: flat cap there
layout(location = 3) in vec4 a_color1;        // colour at the end; w: flat cap there
layout(location = 4) in vec2 a_arc;           // the path's arc length at the start and the end

uniform vec2 u_image_size;

out vec2 v_px;                   // this fragment's image position
flat out vec4 v_ends;
flat out vec4 v_radius_depth;
flat out vec4 v_color0;
flat out vec4 v_color1;
flat out vec2 v_arc;

void main() {
    vec2 a = a_ends.xy, b = a_ends.zw;
    vec2 d = b - a;
    float len = length(d);
    vec2 t = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 n = vec2(-t.y, t.x);
    float r = max(a_radius_depth.x, a_radius_depth.y) + 1.0;
    float along = (gl_VertexID & 1) == 0 ? -r : len + r;
    float across = (gl_VertexID & 2) == 0 ? -r : r;
    v_px = a + t * along + n * across;
    v_ends = a_ends;
    v_radius_depth = a_radius_depth;
    v_color0 = a_color0;
    v_color1 = a_color1;
    v_arc = a_arc;
    vec2 ndc = vec2(v_px.x / u_image_size.x * 2.0 - 1.0, 1.0 - v_px.y / u_image_size.y * 2.0);
    gl_Position = vec4(ndc, 0.0, 1.0);
}
