#version 450 core
// Debug view `view`: world-space unit vector towards the viewer, 0.5 * v + 0.5
// (the view-vector pass of image-space suggestive contours, Qu, Chen & Zwicker 2022, fig. 8b).
#include "common/surface.glsl"
void shade() { o_color = vec4(0.5 * surface().v + 0.5, 1.0); }
