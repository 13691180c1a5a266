// Files embedded into the binary at build time by cmake/embed_files.cmake (shaders, style
// presets), so the binary runs from any directory.
#pragma once

namespace inkshade {

struct EmbeddedFile {
    const char* path;      // relative to the embedded folder, e.g. "shading/lambert.frag"
    const char* contents;  // NUL-terminated
};

}  // namespace inkshade
