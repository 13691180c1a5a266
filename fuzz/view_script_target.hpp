// What fuzz_view_script does with one input: parse_script (scene/view_script.hpp, the format of
// `inkshade view --script`) on the bytes. Errors must be one line starting with the source;
// commands must come in line order with the values the parser promises (finite vectors, a
// positive zoom, frames 0..10⁶, an upper-case letter or digit for a key).
#pragma once
#include <cctype>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_common.hpp"
#include "scene/view_script.hpp"

namespace inkshade::fuzz {

inline void check_script_command(const ScriptCommand& c, int previous_line) {
    if (c.line <= previous_line) broken("commands out of line order");
    if (!std::isfinite(c.vector.x) || !std::isfinite(c.vector.y) || !std::isfinite(c.vector.z))
        broken("a command with a non-finite number");
    if (c.kind == ScriptCommand::Frames && (c.count < 0 || c.count > 1000000)) broken("frames out of range");
    if (c.kind == ScriptCommand::Key && !(std::isdigit(c.count) || (c.count >= 'A' && c.count <= 'Z')))
        broken("a key that is not an upper-case letter or digit");
    if (c.kind == ScriptCommand::Zoom && !(c.vector.x > 0.0f)) broken("a zoom factor that is not positive");
    if (c.kind == ScriptCommand::Gui && c.count != 0 && c.count != 1) broken("gui neither on nor off");
    const bool names = c.kind == ScriptCommand::StyleName || c.kind == ScriptCommand::Open ||
                       c.kind == ScriptCommand::Screenshot || c.kind == ScriptCommand::SaveFrame ||
                       c.kind == ScriptCommand::SaveStyle;
    if (names && c.argument.empty()) broken("a command without its name or path");
    if (c.kind == ScriptCommand::Set && c.argument.find('=') == std::string::npos) broken("set without '='");
}

inline void view_script_input(std::string_view data) {
    const std::string source = "script.txt";
    try {
        const std::vector<ScriptCommand> commands = parse_script(data, source);
        if (commands.size() > kMaxScriptCommands) broken("more commands than the limit");
        int line = 0;
        for (const ScriptCommand& c : commands) {
            check_script_command(c, line);
            line = c.line;
        }
    } catch (const InputError& e) {
        const std::string what = e.what();
        if (what.find('\n') != std::string::npos || what.find('\r') != std::string::npos)
            broken("multi-line error: " + what);
        if (what.rfind(source + ":", 0) != 0) broken("error does not start with the source: " + what);
    }
}

}  // namespace inkshade::fuzz
