#version 450 core
// Shadow-map pass: depth of the mesh as seen from the light.
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_light_view_proj;
void main() { gl_Position = u_light_view_proj * u_model * vec4(a_position, 1.0); }
