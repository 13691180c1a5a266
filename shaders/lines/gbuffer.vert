#version 450 core
// G-buffer pass vertex stage: world position and normal (as mesh.vert, model matrix = identity
// as the renderer draws it) and the object id (render/gpu_mesh.hpp attribute 4), flat.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 4) in uint a_object_id;

uniform mat4 u_view_proj;
#include "common/back_face_push.glsl"

out vec3 v_world_pos;
out vec3 v_world_normal;
flat out uint v_object_id;

void main() {
    v_world_pos = a_position;
    v_world_normal = a_normal;
    v_object_id = a_object_id;
    gl_Position = pushed_back(u_view_proj * vec4(a_position, 1.0));
}
