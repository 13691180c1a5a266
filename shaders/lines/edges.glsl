// edges: discontinuities of the G-buffer around pixel p, taps at spacing s = u_edges_spacing
// pixels (about width / 2, so lines are about `width` pixels wide, centred on the edge):
//  - ids (EDGES_IDS): any of the 8 taps has another object id (silhouettes: background is id 0);
//  - depth (EDGES_DEPTH): max over the 4 directions o of |z(p+o) + z(p-o) - 2 z(p)| / z(p),
//    z = linear depth: a second difference, 0 on planes of any slope (a first-derivative Sobel
//    would fire on slanted planes), large across depth jumps (parts in front of others);
//  - normals (EDGES_NORMAL): the 3x3 Sobel operator on the unit face normal (Sobel over a
//    normal render target, as in Saito & Takahashi 1990's G-buffer edges), magnitude sqrt(|Gx|^2 + |Gy|^2) / 4, which is
//    |n1 - n2| = 2 sin(angle/2) across a crease; background taps take the centre's normal.
//    EDGES_CANNY: Canny (1986) on that magnitude: non-maximum suppression along the gradient
//    direction (quantised to 4), double threshold (t, t/2) with one hysteresis step along the
//    edge: a weak pixel stays when a neighbour along the edge is strong. Lines 1 px wide.
// Coverage ramps from 0 at the threshold to 1 at 1.5 x threshold (weak edges fade).
uniform int u_edges_spacing;
uniform float u_edges_depth_threshold;
uniform float u_edges_normal_threshold;

// Sobel gradient (x, y columns) and magnitude of the face normal at q, spacing s.
float normal_sobel(ivec2 q, int s, out vec2 dir) {
    vec3 c = face_normal_at(q);
    uint cid = gbuffer_at(q).id;
    vec3 n[9];
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            ivec2 t = q + ivec2(i, j) * s;
            n[(j + 1) * 3 + (i + 1)] = gbuffer_at(t).id == 0u || cid == 0u ? c : face_normal_at(t);
        }
    vec3 gx = (n[2] + 2.0 * n[5] + n[8]) - (n[0] + 2.0 * n[3] + n[6]);
    vec3 gy = (n[6] + 2.0 * n[7] + n[8]) - (n[0] + 2.0 * n[1] + n[2]);
    // Direction of steepest change: the sign of the dominant component pair.
    float sx = dot(gx, gx), sy = dot(gy, gy);
    dir = vec2(sqrt(sx), sqrt(sy) * (dot(gx, gy) < 0.0 ? -1.0 : 1.0));
    return sqrt(sx + sy) * 0.25;
}

float ramp(float value, float threshold) {
    return clamp((value - threshold) / max(0.5 * threshold, 1e-6), 0.0, 1.0);
}

float edges_coverage(ivec2 p) {
    int s = max(u_edges_spacing, 1);
    GSample c = gbuffer_at(p);
    float coverage = 0.0;
#if EDGES_IDS
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i)
            if (gbuffer_at(p + ivec2(i, j) * s).id != c.id) coverage = 1.0;
#endif
#if EDGES_DEPTH
    {
        const ivec2 dirs[4] = ivec2[4](ivec2(1, 0), ivec2(0, 1), ivec2(1, 1), ivec2(1, -1));
        float m = 0.0;
        for (int k = 0; k < 4; ++k) {
            float zp = gbuffer_at(p + dirs[k] * s).depth, zm = gbuffer_at(p - dirs[k] * s).depth;
            m = max(m, abs(zp + zm - 2.0 * c.depth) / max(min(c.depth, min(zp, zm)), 1e-6));
        }
        coverage = max(coverage, ramp(m, u_edges_depth_threshold));
    }
#endif
#if EDGES_NORMAL
    if (c.id != 0u) {
#if EDGES_CANNY
        vec2 g;
        float m = normal_sobel(p, 1, g);
        float t = u_edges_normal_threshold;
        if (m > 0.5 * t) {
            // Quantised gradient direction and the direction along the edge.
            float a = atan(g.y, g.x);
            int k = int(round(a / 0.78539816)) & 3;
            const ivec2 steps[4] = ivec2[4](ivec2(1, 0), ivec2(1, 1), ivec2(0, 1), ivec2(-1, 1));
            ivec2 across = steps[k], along = steps[(k + 2) & 3];
            vec2 unused;
            float m1 = normal_sobel(p + across, 1, unused), m2 = normal_sobel(p - across, 1, unused);
            bool peak = m >= m1 && m > m2;
            bool strong = m > t;
            if (peak && !strong)
                strong = normal_sobel(p + along, 1, unused) > t || normal_sobel(p - along, 1, unused) > t;
            if (peak && strong) coverage = 1.0;
        }
#else
        vec2 g;
        coverage = max(coverage, ramp(normal_sobel(p, s, g), u_edges_normal_threshold));
#endif
    }
#endif
    return coverage;
}
