#version 450 core
// stroke: coverage of the capsule around segment a-b whose radius goes linearly from r0 to r1
// (distance to the closest point a + t (b - a), inside when <= mix(r0, r1, t)); an end marked
// flat (a path's butt or square cap) cuts the capsule square there: nothing beyond the end
// point along the segment.
//  - multisampled targets: each sample inside the capsule sets its bit of gl_SampleMask
//    (positions from interpolateAtSample), alpha = opacity: exact coverage, and with the
//    stencil (render/stroke_pass.cpp) a sample is blended once per draw;
//  - single-sampled: alpha = opacity * clamp(r - distance + 0.5, 0, 1) at the pixel centre.
// Colour: the ends' colours blended along the segment.
// Brush (u_brush): the texture at (arc length / u_brush_length, across), across going from 0 on
// the stroke's right edge to 1 on its left, multiplies alpha; the arc length runs on from the
// path's start through every segment, so the pattern does not restart at joins.
// Depth: window depth interpolated along the segment minus a bias (lines lie on the surface).
in vec2 v_px;
flat in vec4 v_ends;
flat in vec4 v_radius_depth;
flat in vec4 v_color0;
flat in vec4 v_color1;
flat in vec2 v_arc;

uniform vec4 u_color;  // rgb (unused: per-vertex colours), opacity
uniform float u_depth_bias;
uniform int u_depth_test;
uniform int u_multisample;
uniform int u_brush;
uniform sampler2D u_brush_texture;
uniform float u_brush_length;

layout(location = 0) out vec4 o_color;

// Signed distance to the capsule's border (negative inside); t = parameter of the closest point.
float capsule(vec2 p, out float t) {
    vec2 a = v_ends.xy, b = v_ends.zw, ab = b - a;
    float l2 = dot(ab, ab);
    float raw = l2 > 0.0 ? dot(p - a, ab) / l2 : 0.0;
    t = clamp(raw, 0.0, 1.0);
    float d = length(p - (a + t * ab)) - mix(v_radius_depth.x, v_radius_depth.y, t);
    // A flat end: the signed distance to the end's line, beyond it.
    float len = sqrt(l2);
    if (v_color0.w > 0.5 && raw < 0.0) d = max(d, -raw * len);
    if (v_color1.w > 0.5 && raw > 1.0) d = max(d, (raw - 1.0) * len);
    return d;
}

// The brush's value at p: arc length along the segment (on beyond its ends, into the caps) and
// the signed distance from its axis over the radius there.
float brush(vec2 p) {
    vec2 a = v_ends.xy, ab = v_ends.zw - a;
    float len = length(ab);
    vec2 t = len > 1e-6 ? ab / len : vec2(1.0, 0.0);
    float along = dot(p - a, t);
    float s = v_arc.x + (len > 1e-6 ? along / len * (v_arc.y - v_arc.x) : along);
    float r = max(mix(v_radius_depth.x, v_radius_depth.y, clamp(along / max(len, 1e-6), 0.0, 1.0)), 1e-3);
    float across = clamp(0.5 + 0.5 * (t.x * (p - a).y - t.y * (p - a).x) / r, 0.0, 1.0);
    return texture(u_brush_texture, vec2(s / u_brush_length, across)).r;
}

void main() {
    float t;
    float alpha = u_color.a;
    // Before any discard: the texture's level of detail needs the neighbours' coordinates.
    if (u_brush == 1) alpha *= brush(v_px);
    if (u_multisample == 1) {
        int mask = 0;
        for (int i = 0; i < gl_NumSamples; ++i) {
            float ts;
            if (capsule(interpolateAtSample(v_px, i), ts) <= 0.0) mask |= 1 << i;
        }
        if (mask == 0) discard;
        gl_SampleMask[0] = mask;
        capsule(v_px, t);
    } else {
        float coverage = clamp(0.5 - capsule(v_px, t), 0.0, 1.0);
        if (coverage <= 0.0) discard;
        alpha *= coverage;
    }
    gl_FragDepth = u_depth_test == 1 ? mix(v_radius_depth.z, v_radius_depth.w, t) - u_depth_bias : 0.0;
    o_color = vec4(mix(v_color0.rgb, v_color1.rgb, t), alpha);
}
