// The viewer's side of `view --script` (the format and its parser: scene/view_script.hpp):
// checking a parsed script against the scene before the window opens. script_runner.hpp runs it.
#pragma once
#include <string>
#include <vector>

#include "inkshade/scene.hpp"
#include "inkshade/style.hpp"
#include "scene/view_script.hpp"

namespace inkshade::viewer {

// Checks, before the window opens, what the commands name as the window will meet it: every
// `set` against the style it applies to (the scene's, then as `style` lines and the F and 1-9
// keys change it), every `style` name or file (load_style), and every `open` model (loaded
// with the scene's options, its file camera and lights as the scene asks). Throws
// InputError("FILE:LINE: problem") for the first bad one; `path` is the script's.
void check_script(const std::vector<ScriptCommand>& commands, const Scene& scene, const std::string& path);

// Applies a `set` (inkshade::apply_override) with the error text --set uses.
void apply_set(Style& style, const std::string& text);

}  // namespace inkshade::viewer
