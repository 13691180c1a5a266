#version 450 core
// G-buffer of the image-space line types (src/render/gbuffer.hpp), one sample per pixel:
//   location 0 (RGBA32F): n.v, linear view depth, object id bits (a flat vertex attribute;
//                         0 = background), packHalf2x16(view-space w.xy)
//   location 1 (RGBA8_SNORM, INKSHADE_GBUFFER_FACE_NORMALS): face normal dFdx(p) x dFdy(p),
//                         view space (faces the viewer by construction)
// n is the interpolated normal turned towards the viewer on back faces (seen_normal, as
// common/surface.glsl),
// w = v - (n.v) n (the projected view vector of DeCarlo et al. 2003).
#include "common/lighting.glsl"

in vec3 v_world_pos;
in vec3 v_world_normal;
flat in uint v_object_id;

uniform mat4 u_view;

layout(location = 0) out vec4 o_surface;
#if INKSHADE_GBUFFER_FACE_NORMALS
layout(location = 1) out vec4 o_face_normal;
#endif

void main() {
    vec3 v = to_viewer(v_world_pos);
    vec3 n = seen_normal(normalize(v_world_normal), v, gl_FrontFacing);
    float ndotv = dot(n, v);
    vec3 p_view = (u_view * vec4(v_world_pos, 1.0)).xyz;
    vec2 w_view = (u_view * vec4(v - ndotv * n, 0.0)).xy;
    o_surface = vec4(ndotv, -p_view.z, uintBitsToFloat(v_object_id), uintBitsToFloat(packHalf2x16(w_view)));
#if INKSHADE_GBUFFER_FACE_NORMALS
    o_face_normal = vec4(normalize(cross(dFdx(p_view), dFdy(p_view))), 0.0);
#endif
}
