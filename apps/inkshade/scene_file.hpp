// `render --scene FILE`: a three.js-like scene description (docs/threejs.md) filling every
// option the command line does not give, so a scene and the equivalent flags render the same.
#pragma once
#include <string>

#include <CLI/CLI.hpp>

#include "scene_options.hpp"

namespace inkshade::cli {

// Loads the scene and sets, in `options`, the model, style (SceneOptions::scene_style), size,
// samples, camera and light placement, except those whose option `cmd` was given explicitly.
// Throws InputError "FILE: FIELD: problem".
void apply_scene_file(const std::string& path, const CLI::App& cmd, SceneOptions& options);

}  // namespace inkshade::cli
