#version 450 core
// stroke joins: coverage of the convex polygon V, A, T, B (shaders/lines/stroke_join.vert) as
// stroke.frag covers its capsules: per sample with MSAA (gl_SampleMask; the stencil keeps a
// sample from being blended twice where the join meets its segments), else the pixel coverage
// as alpha. The two sides along the segments' flat ends (V-A and B-V) are moved a little into
// the segments so no seam shows between them without MSAA. Signed distance of a convex polygon:
// the largest signed distance to its edges' lines (exact inside, a little short of the true
// distance beyond a corner, which only widens the anti-aliasing there).
in vec2 v_px;
flat in vec4 v_va;
flat in vec4 v_tb;
flat in vec4 v_color_depth;
flat in vec4 v_arc;

uniform vec4 u_color;  // opacity in w
uniform float u_depth_bias;
uniform int u_depth_test;
uniform int u_multisample;
uniform int u_brush;
uniform sampler2D u_brush_texture;
uniform float u_brush_length;

layout(location = 0) out vec4 o_color;

float edge(vec2 p, vec2 a, vec2 b, float orientation, float shift) {
    vec2 e = b - a;
    float l = length(e);
    if (l < 1e-6) return -1e6;
    vec2 n = orientation * vec2(e.y, -e.x) / l;  // outward
    return dot(p - a, n) - shift;
}

float polygon(vec2 p) {
    vec2 V = v_va.xy, A = v_va.zw, T = v_tb.xy, B = v_tb.zw;
    // Orientation from the signed area (twice) of V, A, B.
    float area = (A.x - V.x) * (B.y - V.y) - (A.y - V.y) * (B.x - V.x);
    float o = area > 0.0 ? 1.0 : -1.0;
    float inner = v_arc.w;
    float d = edge(p, V, A, o, inner);
    d = max(d, edge(p, A, T, o, 0.0));
    d = max(d, edge(p, T, B, o, 0.0));
    d = max(d, edge(p, B, V, o, inner));
    return d;
}

void main() {
    float alpha = u_color.a;
    if (u_brush == 1) {
        // The brush at the vertex's arc length, across from the middle to the outer edge.
        float across = 0.5 + 0.5 * v_arc.y * clamp(length(v_px - v_va.xy) / max(v_arc.z, 1e-3), 0.0, 1.0);
        alpha *= texture(u_brush_texture, vec2(v_arc.x / u_brush_length, across)).r;
    }
    if (u_multisample == 1) {
        int mask = 0;
        for (int i = 0; i < gl_NumSamples; ++i)
            if (polygon(interpolateAtSample(v_px, i)) <= 0.0) mask |= 1 << i;
        if (mask == 0) discard;
        gl_SampleMask[0] = mask;
    } else {
        float coverage = clamp(0.5 - polygon(v_px), 0.0, 1.0);
        if (coverage <= 0.0) discard;
        alpha *= coverage;
    }
    gl_FragDepth = u_depth_test == 1 ? v_color_depth.w - u_depth_bias : 0.0;
    o_color = vec4(v_color_depth.rgb, alpha);
}
