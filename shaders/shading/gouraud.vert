#version 450 core
// gouraud: Lambert evaluated per vertex, C * (E * max(n.l, 0) + A), colour interpolated
// across each triangle (Gouraud 1971, "Continuous Shading of Curved Surfaces").
#include "common/lighting.glsl"
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
#ifdef INKSHADE_BASE_TEXTURE
layout(location = 5) in vec2 a_uv;  // the texture modulates per pixel (gouraud.frag)
out vec2 v_uv;
#endif

uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform mat3 u_normal_matrix;
#include "common/back_face_push.glsl"

out vec3 v_world_pos;
out vec3 v_world_normal;
out vec3 v_color;
out vec3 v_object_pos;  // model space, for surface-attached patterns (voronoi, stipple)

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    vec3 n = normalize(u_normal_matrix * a_normal);
    vec3 l = to_light(world.xyz);
    v_world_pos = world.xyz;
    v_world_normal = n;
#ifdef INKSHADE_BASE_COLOR_ONLY
    vec3 mesh_color = vec3(1.0);  // the base colour alone (mesh.vert)
#else
    vec3 mesh_color = a_color;
#endif
    v_color = u_base_color * mesh_color * (u_light_color * lambert(n, l) + u_ambient);
#ifdef INKSHADE_UNLIT
    if (u_unlit == 1) v_color = mesh_color;  // as it is: common/shading_main.glsl multiplies the base
#endif
    v_object_pos = a_position;
#ifdef INKSHADE_BASE_TEXTURE
    v_uv = a_uv;
#endif
    gl_Position = pushed_back(u_view_proj * world);
}
