// GLSL sources embedded at build time by cmake/embed_files.cmake.
#pragma once
#include <string>
#include <vector>

#include "core/embedded_file.hpp"

namespace inkshade::gpu {

// Every file under shaders/, paths relative to it (e.g. "shading/lambert.frag").
const std::vector<EmbeddedFile>& embedded_shaders();

// Source of one embedded shader with `#include "file"` lines expanded (paths relative to
// shaders/). Throws RuntimeError when a file is missing.
std::string shader_source(const std::string& path);

}  // namespace inkshade::gpu
