#version 450 core
// Image-space line types in one full-screen pass over the G-buffer (full-screen passes are
// the expensive part on a software rasteriser): edges, then suggestive-image, each mixed over
// the previous with its colour, opacity and coverage; the result is blended "over" the image
// (premultiplied).
#include "lines/gbuffer_read.glsl"
#if EDGES
#include "lines/edges.glsl"
uniform vec4 u_edges_color;  // rgb, opacity
#endif
#if SUGGESTIVE
#include "lines/suggestive_image.glsl"
uniform vec4 u_sc_color;
#endif

layout(location = 0) out vec4 o_color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 color = vec3(0.0);
    float alpha = 0.0;
#if EDGES
    {
        float a = u_edges_color.a * edges_coverage(p);
        color = mix(color, u_edges_color.rgb, a);
        alpha = alpha + a * (1.0 - alpha);
    }
#endif
#if SUGGESTIVE
    {
        float a = u_sc_color.a * suggestive_coverage(p);
        color = color * (1.0 - a) + u_sc_color.rgb * a;
        alpha = alpha + a * (1.0 - alpha);
    }
#endif
    if (alpha <= 0.0) discard;
    o_color = vec4(color, alpha);
}
