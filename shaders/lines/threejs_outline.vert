#version 450 core
// threejs-outline: three.js's OutlineEffect (examples/jsm/effects/OutlineEffect.js, r187). Back
// faces of the mesh, each vertex moved in clip space along the clip-space image of its normal,
// normalised as a 4-vector:
//   d = view_proj * (n, 0)      (OutlineEffect: pos - projection(p - n), the same vector)
//   clip' = clip + d / |d| * thickness * clip.w
// so the image moves by about `thickness` in normalised device coordinates (thickness * H / 2
// pixels), whatever the distance. The mesh's own normals are used, as three.js does (split
// normals at creases open gaps there; `hull` welds them).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_view_proj;
uniform float u_thickness;
#include "common/back_face_push.glsl"

void main() {
    vec4 clip = u_view_proj * vec4(a_position, 1.0);
    vec4 d = u_view_proj * vec4(a_normal, 0.0);
    float len = length(d);
    gl_Position = pushed_back(len > 0.0 ? clip + d * (u_thickness * clip.w / len) : clip);
}
