#version 450 core
// Shared vertex stage of every shading model: world-space position, normal and colour, and
// the uvs of a textured mesh (INKSHADE_BASE_TEXTURE: a program variant, so untextured meshes
// pay nothing; common/surface.glsl samples the texture). INKSHADE_BASE_COLOR_ONLY: the
// vertex/material colours are left out, C is the base colour alone (BaseColorUse::Only).
// INKSHADE_MTOON_OUTLINE: mtoon's outline draw, vertices moved out (shading/mtoon_outline.glsl);
// INKSHADE_MTOON_TEXTURES: a VRM material's MToon textures, read at the uvs.
// INKSHADE_VERTEX_ATTRIBUTES: the vertex attributes the model declares (locations 6 on), and
// INKSHADE_PASS_VERTEX_ATTRIBUTES their copies to the fragment stage, both generated from the
// declaration (render/shading_inputs.hpp).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
#if defined(INKSHADE_BASE_TEXTURE) || defined(INKSHADE_MTOON_TEXTURES)
layout(location = 5) in vec2 a_uv;
out vec2 v_uv;
#endif
#ifdef INKSHADE_VERTEX_ATTRIBUTES
INKSHADE_VERTEX_ATTRIBUTES
#endif

uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform mat3 u_normal_matrix;
#include "common/back_face_push.glsl"
#ifdef INKSHADE_MTOON_OUTLINE
#include "shading/mtoon_outline.glsl"
#endif

out vec3 v_world_pos;
out vec3 v_world_normal;
out vec3 v_color;
out vec3 v_object_pos;  // model space, for surface-attached patterns (voronoi, stipple)

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world_pos = world.xyz;
    v_world_normal = u_normal_matrix * a_normal;
#ifdef INKSHADE_BASE_COLOR_ONLY
    v_color = vec3(1.0);
#else
    v_color = a_color;
#endif
    v_object_pos = a_position;
#if defined(INKSHADE_BASE_TEXTURE) || defined(INKSHADE_MTOON_TEXTURES)
    v_uv = a_uv;
#endif
#ifdef INKSHADE_PASS_VERTEX_ATTRIBUTES
    INKSHADE_PASS_VERTEX_ATTRIBUTES
#endif
    vec4 clip = u_view_proj * world;
#ifdef INKSHADE_MTOON_OUTLINE
    clip = mtoon_outline_position(clip, world.xyz, a_normal, outline_width_multiply());
#endif
    gl_Position = pushed_back(clip);
}
