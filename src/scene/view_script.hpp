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
// The library reads the text (no window and no GL here, so the fuzzer reaches it: fuzz_view_script);
// the viewer checks the commands against its scene and runs them (apps/viewer).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace inkshade {

struct ScriptCommand {
    enum Kind { Frames, Key, Set, StyleName, LightPos, Orbit, Zoom, Open, Screenshot, SaveFrame, SaveStyle, Gui, Quit };
    Kind kind = Quit;
    std::string argument;    // paths, names, set text
    int count = 0;           // frames, key code (GLFW = upper-case ASCII), gui on/off
    glm::vec3 vector{0.0f};  // light-pos; orbit (yaw, pitch); zoom (factor)
    int line = 0;            // in the script file, for messages
};

// The most commands a script may hold (a longer one is an error, not an allocation).
inline constexpr size_t kMaxScriptCommands = 100000;

// Parses one script line (no comment, trimmed); throws InputError with the problem.
ScriptCommand parse_script_line(const std::string& line);

// Parses a whole script's text, `source` naming it in errors: InputError("SOURCE:LINE: problem"),
// one line, for the first bad line. Lines end in \n (a \r before it is a blank).
std::vector<ScriptCommand> parse_script(std::string_view text, const std::string& source);

// Reads and parses the script file at `path` (InputError("PATH: cannot open script") if it
// cannot be read), so a typo fails before the window opens.
std::vector<ScriptCommand> read_script(const std::string& path);

}  // namespace inkshade
