#version 450 core
// hull: the line colour with its opacity (blended "over" by the pass).
uniform vec4 u_color;
layout(location = 0) out vec4 o_color;
void main() { o_color = u_color; }
