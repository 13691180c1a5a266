#version 450 core
// The aov pass's geometry buffers (src/render/aov_pass.cpp), one sample per pixel:
//   location 0 (RGBA32F): camera-space unit normal (x right, y up, z towards the viewer), turned
//                         towards the viewer on back faces as the shading shows them
//                         (seen_normal); linear depth along the view axis (-z)
//   location 1 (R32UI):   object id (render/gpu_mesh.hpp attribute 4; 0 = background)
#include "common/lighting.glsl"

in vec3 v_world_pos;
in vec3 v_world_normal;
flat in uint v_object_id;

uniform mat4 u_view;

layout(location = 0) out vec4 o_normal_depth;
layout(location = 1) out uint o_object_id;

void main() {
    vec3 v = to_viewer(v_world_pos);
    vec3 n = seen_normal(normalize(v_world_normal), v, gl_FrontFacing);
    o_normal_depth = vec4(normalize(mat3(u_view) * n), -(u_view * vec4(v_world_pos, 1.0)).z);
    o_object_id = v_object_id;
}
