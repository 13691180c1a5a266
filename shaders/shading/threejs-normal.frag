#version 450 core
// threejs-normal: three.js r187 MeshNormalMaterial: the view-space unit normal as 0.5 * n + 0.5,
// written without the sRGB encode (meshnormal_frag has no colorspace_fragment).
#include "common/surface.glsl"
uniform mat4 u_view;  // world to view (camera) space

void shade() {
    vec3 n = normalize(mat3(u_view) * surface().n);
    o_color = vec4(0.5 * n + 0.5, 1.0);
}
