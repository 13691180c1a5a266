// GLSL sources embedded at build time by cmake/embed_files.cmake, their #include lines already
// expanded there (shader_source.hpp looks them up).
#pragma once
#include <vector>

#include "core/embedded_file.hpp"

namespace inkshade::gpu {

// Every file under shaders/, paths relative to it (e.g. "shading/lambert.frag").
const std::vector<EmbeddedFile>& embedded_shaders();

}  // namespace inkshade::gpu
