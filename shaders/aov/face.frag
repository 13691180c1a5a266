#version 450 core
// The face drawn at each pixel for the surface fields (src/render/field_samples_pass.cpp):
//   location 0 (R32UI): face index + 1 (GpuMesh::draw draws the faces in order, u_face_base
//                       the first face of the draw call; 0 = background)
uniform int u_face_base;

layout(location = 0) out uint o_face;

void main() { o_face = uint(u_face_base + gl_PrimitiveID) + 1u; }
