#version 450 core
// gouraud: the vertex stage already lit the vertices; interpolate their colours. A base-colour
// texture modulates the interpolated colour per pixel (lighting per vertex, texture per pixel,
// as fixed-function Gouraud with GL_MODULATE did).
#include "common/surface.glsl"

void shade() {
    vec3 c = v_color;
#ifdef INKSHADE_BASE_TEXTURE
    c *= texture(u_base_texture, base_uv()).rgb;
#endif
    o_color = encode_output(c);
}
