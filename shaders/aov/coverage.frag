#version 450 core
// The foreground mask (src/render/aov_pass.cpp): 1 in every sample the mesh covers; the MSAA
// resolve averages the samples into the pixel's coverage.
layout(location = 0) out vec4 o_coverage;

void main() { o_coverage = vec4(1.0); }
