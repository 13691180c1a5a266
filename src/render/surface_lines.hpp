// What the shading pass adds to a shading model when `rim-contour` is on: its fragment test,
// run by every model's main after the model's shade() (shaders/common/shading_main.glsl and
// shaders/lines/surface_lines.glsl), compiled in by a #define: every model gets it without
// being edited and without another pass.
#pragma once
#include <string>

#include "gpu/shader_program.hpp"
#include "inkshade/lines.hpp"

namespace inkshade::render {

struct SurfaceLines {
    const LineSettings* rim = nullptr;  // rim-contour settings, or none

    bool active() const { return rim != nullptr; }
    // Fragment-shader `#define`s of the variant (empty when inactive; part of the program
    // cache key): INKSHADE_RIM_CONTOUR and INKSHADE_RIM_COMPENSATE.
    std::string defines() const;
    // The rim test's uniforms.
    void upload(gpu::ShaderProgram& program) const;
};

}  // namespace inkshade::render
