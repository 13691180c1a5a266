#version 450 core
// threejs-basic: three.js r187 MeshBasicMaterial, unlit: sRGB(C x color).
#include "common/surface.glsl"
#include "common/threejs.glsl"
uniform vec3 u_color;  // linear (the parameter is sRGB, decoded on the CPU)

void shade() { o_color = threejs_output(surface().albedo * u_color); }
