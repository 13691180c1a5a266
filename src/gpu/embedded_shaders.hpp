// GLSL sources embedded at build time by cmake/embed_shaders.cmake.
#pragma once
#include <string>
#include <vector>

namespace inkshade::gpu {

struct EmbeddedShader {
    const char* path;    // relative to shaders/, e.g. "shading/lambert.frag"
    const char* source;  // NUL-terminated
};

const std::vector<EmbeddedShader>& embedded_shaders();

// Source of one embedded shader with `#include "file"` lines expanded (paths relative to
// shaders/). Throws RuntimeError when a file is missing.
std::string shader_source(const std::string& path);

}  // namespace inkshade::gpu
