// Files embedded into the binary at build time by cmake/embed_files.cmake (shaders, style
// presets), so the binary runs from any directory.
#pragma once
#include <cstddef>

namespace inkshade {

struct EmbeddedFile {
    const char* path;      // relative to the embedded folder, e.g. "shading/lambert.frag"
    const char* contents;  // NUL-terminated
};

// A binary file (an image) embedded byte for byte by cmake/embed_binary_files.cmake.
struct EmbeddedBinary {
    const char* path;  // relative to the embedded folder, e.g. "ink.png"
    const unsigned char* bytes;
    size_t size;
};

}  // namespace inkshade
