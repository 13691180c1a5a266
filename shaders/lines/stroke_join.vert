#version 450 core
// stroke joins (render/stroke_pass.cpp): one instance per miter or bevel corner of a path, the
// convex polygon V, A, T, B that fills the outside of the corner between the two segments' flat
// ends (V the vertex, A and B the outer corners of the incoming and outgoing segment, T the
// miter's tip, or the middle of A and B for a bevel), drawn as a quad around it plus one pixel.
layout(location = 0) in vec4 a_va;           // V, A
layout(location = 1) in vec4 a_tb;           // T, B
layout(location = 2) in vec4 a_color_depth;  // rgb, window depth at V
layout(location = 3) in vec4 a_arc;          // arc length at V, outer side (-1 right, 1 left), radius at V, inner offset

uniform vec2 u_image_size;

out vec2 v_px;
flat out vec4 v_va;
flat out vec4 v_tb;
flat out vec4 v_color_depth;
flat out vec4 v_arc;

void main() {
    vec2 lo = min(min(a_va.xy, a_va.zw), min(a_tb.xy, a_tb.zw)) - 2.0;
    vec2 hi = max(max(a_va.xy, a_va.zw), max(a_tb.xy, a_tb.zw)) + 2.0;
    v_px = vec2((gl_VertexID & 1) == 0 ? lo.x : hi.x, (gl_VertexID & 2) == 0 ? lo.y : hi.y);
    v_va = a_va;
    v_tb = a_tb;
    v_color_depth = a_color_depth;
    v_arc = a_arc;
    vec2 ndc = vec2(v_px.x / u_image_size.x * 2.0 - 1.0, 1.0 - v_px.y / u_image_size.y * 2.0);
    gl_Position = vec4(ndc, 0.0, 1.0);
}
