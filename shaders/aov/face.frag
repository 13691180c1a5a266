#version 450 core
// The face drawn at each pixel for the surface fields (src/render/field_samples_pass.cpp):
//   location 0 (R32UI): the mesh's face number + 1, from face.vert (0 = background)
flat in uint v_face;

layout(location = 0) out uint o_face;

void main() { o_face = v_face; }
