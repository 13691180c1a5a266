#version 450 core
// The aov pass's face buffer alone (src/render/aov_pass.cpp), for the surface fields when no
// depth, normal or id AOV is asked for: aov.frag's location 2 without the other two targets.
//   location 0 (R32UI): face index + 1 (u_face_base the first face of the draw call; 0 =
//                       background)
uniform int u_face_base;

layout(location = 0) out uint o_face;

void main() { o_face = uint(u_face_base + gl_PrimitiveID) + 1u; }
