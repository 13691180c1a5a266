#version 450 core
// palette: Inigo Quilez's cosine palette (iquilezles.org, "palettes"):
//   colour(t) = a + b * cos(2 pi (c * t + d))     (a, b, c, d RGB vectors)
// t from the driver: max(n.l, 0), 0.5 n.l + 0.5, max(n.v, 0), or the model-space height
// (y), x or z normalised to [0, 1] over the bounding box. With lit on, the colour is
// multiplied by (E * max(n.l, 0) + A). The base colour C is not used.
#include "common/surface.glsl"

const float kTwoPi = 6.28318530717958647692;

uniform vec3 u_a;
uniform vec3 u_b;
uniform float u_c[3];  // list parameters: one value repeats over r, g, b
uniform float u_d[3];
uniform int u_driver;  // 0 ndotl, 1 half-lambert, 2 ndotv, 3 height (y), 4 x, 5 z
uniform int u_lit;

// Model-space coordinate `axis` mapped to [0, 1] across the bounding box.
float box_fraction(int axis) {
    float extent = u_bbox_max[axis] - u_bbox_min[axis];
    return extent > 0.0 ? clamp((v_object_pos[axis] - u_bbox_min[axis]) / extent, 0.0, 1.0) : 0.0;
}

void shade() {
    Surface s = surface();
    float ndotl = dot(s.n, s.l);
    float t;
    if (u_driver == 0) t = max(ndotl, 0.0);
    else if (u_driver == 1) t = 0.5 * ndotl + 0.5;
    else if (u_driver == 2) t = max(dot(s.n, s.v), 0.0);
    else if (u_driver == 3) t = box_fraction(1);
    else if (u_driver == 4) t = box_fraction(0);
    else t = box_fraction(2);
    vec3 c3 = vec3(u_c[0], u_c[1], u_c[2]);
    vec3 d3 = vec3(u_d[0], u_d[1], u_d[2]);
    vec3 c = u_a + u_b * cos(kTwoPi * (c3 * t + d3));
    if (u_lit == 1) c *= u_light_color * max(ndotl, 0.0) + u_ambient;
    o_color = encode_output(c);
}
