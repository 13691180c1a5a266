// GLSL sources are composed from shared snippets by `#include "path"` lines (paths relative to
// shaders/). The includes are expanded when the build embeds the shaders
// (cmake/embed_files.cmake, EXPAND_INCLUDES): each file once per source, like `#pragma once`,
// so a snippet states what it needs and may be included by several others; a missing include,
// a cycle or a malformed #include line fails the build, naming the including file and line.
// The binary rewrites no shader text: variants differ only by the #defines a program inserts.
#pragma once
#include <string>

namespace inkshade::gpu {

// Source of embedded shader `path` (relative to shaders/), its includes already expanded.
// Throws RuntimeError when `path` is not embedded.
std::string shader_source(const std::string& path);

}  // namespace inkshade::gpu
