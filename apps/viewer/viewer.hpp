// `inkshade view`: a GLFW window showing the rendered model, Dear ImGui panels for the style
// (shading model, parameters, line types), light, camera and background, live timings, and
// save frame / save style. Frames come from the same Renderer as `inkshade render`, so a
// saved frame is the PNG the CLI writes for the same style, camera and size.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "inkshade/scene.hpp"

namespace inkshade::viewer {

struct ViewerOptions {
    // The model (empty: builtin:teapot), style, camera, light and image options as every front
    // end gives them (make_scene); the image size is the window's size in screen coordinates.
    Scene scene;
    bool gui = true;         // H toggles
    std::string script;      // commands run one per frame (see docs/viewer.md)
    std::string screenshot;  // with `frames`: save the window after N frames and exit
    int frames = 0;          // > 0: exit after N frames
};

// Opens the window and runs until it is closed, the script ends or `frames` are shown.
// Throws RuntimeError when there is no display (one line suggesting `inkshade render`).
int run_viewer(const ViewerOptions& options);

}  // namespace inkshade::viewer
