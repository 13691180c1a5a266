// GLSL sources are composed from shared snippets by `#include "path"` lines (paths relative to
// shaders/), expanded when a source is looked up: each file once per source, like
// `#pragma once`, so a snippet states what it needs and may be included by several others.
// Nothing else rewrites a shader: variants differ only by the #defines a program inserts.
#pragma once
#include <functional>
#include <string>

namespace inkshade::gpu {

// Source of embedded shader `path` with its includes expanded. Throws RuntimeError when
// `path` or an include is not embedded, naming the including file and line, and for an
// include cycle or a malformed #include line.
std::string shader_source(const std::string& path);

// The contents of file `path`, or null when there is none.
using ShaderLookup = std::function<const char*(const std::string& path)>;

// shader_source over any set of files (tests give their own).
std::string expand_includes(const std::string& path, const ShaderLookup& lookup);

}  // namespace inkshade::gpu
