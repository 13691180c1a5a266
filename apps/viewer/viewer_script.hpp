// Scripts that drive `inkshade view` without a person (tests, documentation screenshots): one
// command per line, run one per frame; '#' at the start or after a blank starts a comment. Commands:
//   frames N            show N frames before the next command
//   key K               press key K (F, H, S, R, O, 1-9, as in the window)
//   set NAME=VALUE      as --set: [model.]param=value or linetype.param=value
//   style NAME|FILE     load a style
//   light-pos X,Y,Z     move the light (world coordinates)
//   orbit YAW PITCH     orbit the camera by degrees;  zoom FACTOR  (< 1 zooms in)
//   open PATH           load a model (an error keeps the current one)
//   screenshot PATH     save the window's pixels after this frame is drawn
//   save-frame PATH     save the rendered image (what `inkshade render` writes)
//   save-style PATH     save the current style as a preset file
//   gui on|off          show or hide the panels;  quit
// This file reads and checks scripts; script_runner.hpp runs them.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "inkshade/scene.hpp"
#include "inkshade/style.hpp"

namespace inkshade::viewer {

struct ScriptCommand {
    enum Kind { Frames, Key, Set, StyleName, LightPos, Orbit, Zoom, Open, Screenshot, SaveFrame, SaveStyle, Gui, Quit };
    Kind kind = Quit;
    std::string argument;    // paths, names, set text
    int count = 0;           // frames, key code (GLFW = upper-case ASCII), gui on/off
    glm::vec3 vector{0.0f};  // light-pos; orbit (yaw, pitch); zoom (factor)
    int line = 0;            // in the script file, for messages
};

// Reads and checks a whole script first, so a typo fails before the window opens.
// Throws InputError("FILE:LINE: problem").
std::vector<ScriptCommand> read_script(const std::string& path);

// Checks, before the window opens, what the commands name as the window will meet it: every
// `set` against the style it applies to (the scene's, then as `style` lines and the F and 1-9
// keys change it), every `style` name or file (load_style), and every `open` model (loaded
// with the scene's options, its file camera and lights as the scene asks). Throws
// InputError("FILE:LINE: problem") for the first bad one; `path` is the script's.
void check_script(const std::vector<ScriptCommand>& commands, const Scene& scene, const std::string& path);

// Parses one script line (no comment, trimmed); throws InputError with the problem.
ScriptCommand parse_script_line(const std::string& line);

// Applies a `set` (inkshade::apply_override) with the error text --set uses.
void apply_set(Style& style, const std::string& text);

}  // namespace inkshade::viewer
