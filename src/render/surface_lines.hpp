// What the shading pass adds to a shading model when `rim-contour` is on: its fragment test,
// appended to the model's fragment shader (shaders/lines/surface_lines.glsl, the model's main
// renamed), so every model gets it without being edited and without another pass.
#pragma once
#include <string>

#include "gpu/shader_program.hpp"
#include "inkshade/lines.hpp"

namespace inkshade::render {

struct SurfaceLines {
    const LineSettings* rim = nullptr;  // rim-contour settings, or none

    bool active() const { return rim != nullptr; }
    // Fragment-shader `#define`s of the variant (empty when inactive; part of the program
    // cache key), including `#define main inkshade_shading_main`.
    std::string defines() const;
    // GLSL appended to the fragment shader `fragment_path` (its expanded source is inspected
    // for the inputs it already declares).
    std::string epilogue(const std::string& fragment_path) const;
    // The rim test's uniforms.
    void upload(gpu::ShaderProgram& program) const;
};

}  // namespace inkshade::render
