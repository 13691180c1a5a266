#include "gpu/shader_source.hpp"

#include "gpu/embedded_shaders.hpp"
#include "inkshade/error.hpp"

namespace inkshade::gpu {

std::string shader_source(const std::string& path) {
    for (const EmbeddedFile& s : embedded_shaders())
        if (path == s.path) return s.contents;
    throw RuntimeError("shader " + path + " is not embedded in this build");
}

}  // namespace inkshade::gpu
