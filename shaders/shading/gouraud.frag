#version 450 core
// gouraud: the vertex stage already lit the vertices; interpolate their colours.
#include "common/surface.glsl"

void main() { o_color = encode_output(v_color); }
