#version 450 core
// voronoi: 3-D cellular (Worley) noise on the surface (seed 004, "Voronoi shading";
// S. Worley, "A Cellular Texture Basis Function", SIGGRAPH 1996).
//   x = normalized_object_pos() * scale: model space, longest bounding-box side = `scale` cells,
//       so the pattern sticks to the surface and looks the same on any model size or file
//       format (the seed's screen/size-dependent version broke on OBJ models);
//   one feature point per unit cell (pcg3d hash of the cell id), F1/F2 = distances to the
//   nearest / second-nearest point over the 3x3x3 neighbourhood;
//   mode cells:    P = mix(C, palette(hash(id of the F1 cell)), color-mix)
//   mode distance: P = F1 (grey)
//   mode isolines: P = C with lines of edge-color at F1 = k * isoline-spacing
//   edges:   P = mix(P, edge-color, 1 - smoothstep over fwidth of (F2 - F1 - edge-width))
//   lit:     P * (E * max(n.l, 0) + A)
#include "common/surface.glsl"
#include "common/cell_hash.glsl"
uniform float u_scale;
uniform int u_mode;  // 0 cells, 1 distance, 2 isolines
uniform float u_color_mix;
uniform float u_edge_width;
uniform vec3 u_edge_color;
uniform float u_isoline_spacing;
uniform int u_lit;

// Colour of a cell: a cosine palette (Quilez) over a hashed hue, with hashed brightness.
vec3 cell_color(ivec3 c) {
    vec3 h = hash_to_unit(pcg3d(pcg3d(uvec3(c))));
    vec3 hue = 0.5 + 0.5 * cos(6.2831853 * (h.x + vec3(0.0, 0.333333, 0.666667)));
    return mix(vec3(0.15), hue, 0.55 + 0.45 * h.y);
}

void main() {
    Surface s = surface();
    vec3 x = normalized_object_pos() * u_scale;
    ivec3 base = ivec3(floor(x));
    float f1 = 1e9, f2 = 1e9;
    ivec3 id = base;
    for (int k = -1; k <= 1; ++k)
        for (int j = -1; j <= 1; ++j)
            for (int i = -1; i <= 1; ++i) {
                ivec3 c = base + ivec3(i, j, k);
                float d = distance(x, cell_point(c));
                if (d < f1) {
                    f2 = f1;
                    f1 = d;
                    id = c;
                } else if (d < f2) {
                    f2 = d;
                }
            }

    vec3 p;
    if (u_mode == 0) {
        p = mix(s.albedo, cell_color(id), u_color_mix);
    } else if (u_mode == 1) {
        p = vec3(f1);
    } else {
        float t = f1 / u_isoline_spacing;
        float d = abs(fract(t + 0.5) - 0.5);  // distance to the nearest isoline, in spacings
        float w = max(fwidth(t), 1e-6);
        p = mix(u_edge_color, s.albedo, smoothstep(0.5 * w, 1.5 * w, d));
    }
    if (u_edge_width > 0.0) {
        float e = f2 - f1;
        float w = max(fwidth(e), 1e-6);
        p = mix(u_edge_color, p, smoothstep(u_edge_width - 0.5 * w, u_edge_width + 0.5 * w, e));
    }
    if (u_lit == 1) p *= u_light_color * lambert(s.n, s.l) + u_ambient;
    o_color = encode_output(p);
}
