#version 450 core
// Debug view `normal`: world-space unit normal encoded as 0.5 * n + 0.5
// (the normal pass of image-space suggestive contours, Qu, Chen & Zwicker 2022, fig. 8a).
#include "common/surface.glsl"
void shade() { o_color = vec4(0.5 * surface().n + 0.5, 1.0); }
