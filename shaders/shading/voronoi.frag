#version 450 core
// voronoi: 3-D cellular (Worley) noise on the surface ("Voronoi shading";
// S. Worley, "A Cellular Texture Basis Function", SIGGRAPH 1996).
//   x = normalized_object_pos() * scale: model space, longest bounding-box side = `scale` cells,
//       so the pattern sticks to the surface and looks the same on any model size or file
//       format (a pattern from screen or unnormalised positions depends on the model's size);
//   one feature point per unit cell (cell_hash of the cell id, within kCellJitter = 0.3 of the
//   cell centre), F1/F2 = distances to the nearest / second-nearest point over the 2x2x2 cells
//   whose centres surround x (Gustavson's 2x2x2 search; docs/shading.md for its accuracy);
//   mode cells:    P = mix(C, palette(hash(id of the F1 cell)), color-mix)
//   mode distance: P = F1 (grey)
//   mode isolines: P = C with lines of edge-color at F1 = k * isoline-spacing
//   edges:   P = mix(P, edge-color, 1 - smoothstep over fwidth of (F2 - F1 - edge-width))
//   lit:     P * (E * max(n.l, 0) + A)
#include "common/surface.glsl"
#include "common/cell_hash.glsl"
uniform float u_scale;
// INKSHADE_MODE (0 cells, 1 distance, 2 isolines) and INKSHADE_LIT are compile-time parameters.
uniform float u_color_mix;
uniform float u_edge_width;
uniform vec3 u_edge_color;
uniform float u_isoline_spacing;

// Colour of a cell: a cosine palette (Quilez) over a hashed hue, with hashed brightness. The
// three phase-shifted cosines come from one cos/sin pair (cos(a + 2pi/3) etc.).
vec3 cell_color(ivec3 c) {
    vec2 h = bytes_to_unit(cell_hash_mix(cell_hash(c))).xy;
    float a = 6.2831853 * h.x, ca = cos(a), sa = sin(a);
    vec3 hue = 0.5 + 0.5 * vec3(ca, -0.5 * ca - 0.8660254 * sa, -0.5 * ca + 0.8660254 * sa);
    return mix(vec3(0.15), hue, 0.55 + 0.45 * h.y);
}

void shade() {
    Surface s = surface();
    vec3 x = normalized_object_pos() * u_scale;
    // Feature points lie within kCellJitter of their cell centres (cell_point), so the nearest
    // one is (almost always: cell_hash.glsl) among the 2x2x2 cells whose centres surround x;
    // F2 can come from a farther cell, but then it is far from F1 (no edge there).
    ivec3 base = ivec3(floor(x - 0.5));
    // Squared distances in the search (one sqrt per feature, not per cell); the cell hash's
    // per-axis products of neighbouring cells differ by an add (cell_hash.glsl).
    uvec3 k0 = uvec3(base) * kCellHashMul, k1 = k0 + kCellHashMul;
    vec3 xf = x - vec3(base);
    float d1 = 1e18, d2 = 1e18;
    ivec3 id = base;
    for (int k = 0; k <= 1; ++k)
        for (int j = 0; j <= 1; ++j)
            for (int i = 0; i <= 1; ++i) {
                ivec3 o = ivec3(i, j, k);
                uint hc = cell_hash_mix((i == 0 ? k0.x : k1.x) ^ (j == 0 ? k0.y : k1.y) ^ (k == 0 ? k0.z : k1.z));
                vec3 r = vec3(o) + cell_offset(hc) - xf;
                float d = dot(r, r);
                // Insert d into (d1, d2) without branches.
                d2 = min(d2, max(d1, d));
                id = d < d1 ? base + o : id;
                d1 = min(d1, d);
            }
    float f1 = sqrt(d1), f2 = sqrt(d2);

#if INKSHADE_MODE == 0
    vec3 p = mix(s.albedo, cell_color(id), u_color_mix);
#elif INKSHADE_MODE == 1
    vec3 p = vec3(f1);
#else
    float t = f1 / u_isoline_spacing;
    float d = abs(fract(t + 0.5) - 0.5);  // distance to the nearest isoline, in spacings
    float w = max(fwidth(t), 1e-6);
    vec3 p = mix(u_edge_color, s.albedo, smoothstep(0.5 * w, 1.5 * w, d));
#endif
    if (u_edge_width > 0.0) {
        float e = f2 - f1;
        float w = max(fwidth(e), 1e-6);
        p = mix(u_edge_color, p, smoothstep(u_edge_width - 0.5 * w, u_edge_width + 0.5 * w, e));
    }
#if INKSHADE_LIT
    p *= u_light_color * lambert(s.n, s.l) + u_ambient;
#endif
    o_color = encode_output(p);
}
