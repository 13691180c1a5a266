#version 450 core
// The surface fields' face pass (src/render/field_samples_pass.cpp): GpuMesh::draw_face_numbers's
// de-indexed faces, each corner carrying its face's number + 1 (0 = background).
layout(location = 0) in vec3 a_position;
layout(location = 4) in uint a_face;

uniform mat4 u_view_proj;
#include "common/back_face_push.glsl"

flat out uint v_face;

void main() {
    v_face = a_face;
    gl_Position = pushed_back(u_view_proj * vec4(a_position, 1.0));
}
