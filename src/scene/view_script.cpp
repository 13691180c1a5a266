#include "scene/view_script.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "inkshade/error.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {

namespace {

float number(const std::string& text) {
    float v = 0.0f;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v))
        throw InputError(io::quote_token(text) + " is not a number");
    return v;
}

}  // namespace

ScriptCommand parse_script_line(const std::string& line) {
    std::istringstream in(line);
    std::string verb, rest;
    in >> verb;
    std::getline(in >> std::ws, rest);
    while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t' || rest.back() == '\r')) rest.pop_back();
    auto words = [&] {
        std::istringstream w(rest);
        std::vector<std::string> out;
        for (std::string s; w >> s;) out.push_back(s);
        return out;
    };
    auto need = [&](size_t n, const char* usage) {
        auto w = words();
        if (w.size() != n) throw InputError(std::string("expected ") + usage);
        return w;
    };
    ScriptCommand c;
    c.argument = rest;
    if (verb == "frames") {
        c.kind = ScriptCommand::Frames;
        float n = number(need(1, "frames N")[0]);
        if (n < 0 || n > 1e6 || n != std::floor(n)) throw InputError("frames: expected a count 0..1000000");
        c.count = int(n);
    } else if (verb == "key") {
        auto k = need(1, "key K (one letter or digit)")[0];
        if (k.size() != 1 || !std::isalnum(static_cast<unsigned char>(k[0])))
            throw InputError("key: expected one letter or digit, got " + io::quote_token(k));
        c.kind = ScriptCommand::Key;
        c.count = std::toupper(static_cast<unsigned char>(k[0]));  // GLFW key codes are upper-case ASCII
    } else if (verb == "set") {
        if (rest.find('=') == std::string::npos) throw InputError("expected set NAME=VALUE");
        c.kind = ScriptCommand::Set;
    } else if (verb == "style" || verb == "open" || verb == "screenshot" || verb == "save-frame" ||
               verb == "save-style") {
        if (rest.empty()) throw InputError(verb + ": expected a name or path");
        c.kind = verb == "style"        ? ScriptCommand::StyleName
                 : verb == "open"       ? ScriptCommand::Open
                 : verb == "screenshot" ? ScriptCommand::Screenshot
                 : verb == "save-frame" ? ScriptCommand::SaveFrame
                                        : ScriptCommand::SaveStyle;
    } else if (verb == "light-pos") {
        std::string text = rest;
        for (char& ch : text)
            if (ch == ',') ch = ' ';
        std::istringstream w(text);
        std::vector<std::string> parts;
        for (std::string s; w >> s;) parts.push_back(s);
        if (parts.size() != 3) throw InputError("expected light-pos X,Y,Z");
        c.kind = ScriptCommand::LightPos;
        c.vector = {number(parts[0]), number(parts[1]), number(parts[2])};
    } else if (verb == "orbit") {
        auto w = need(2, "orbit YAW PITCH");
        c.kind = ScriptCommand::Orbit;
        c.vector = {number(w[0]), number(w[1]), 0.0f};
    } else if (verb == "zoom") {
        c.kind = ScriptCommand::Zoom;
        c.vector.x = number(need(1, "zoom FACTOR")[0]);
        if (!(c.vector.x > 0.0f)) throw InputError("zoom: the factor must be positive");
    } else if (verb == "gui") {
        auto w = need(1, "gui on|off")[0];
        if (w != "on" && w != "off") throw InputError("gui: expected on or off");
        c.kind = ScriptCommand::Gui;
        c.count = w == "on";
    } else if (verb == "quit") {
        c.kind = ScriptCommand::Quit;
    } else {
        throw InputError("unknown command " + io::quote_token(verb) +
                         " (frames, key, set, style, light-pos, orbit, zoom, open, screenshot, save-frame, "
                         "save-style, gui, quit)");
    }
    return c;
}

std::vector<ScriptCommand> parse_script(std::string_view text, const std::string& source) {
    std::vector<ScriptCommand> out;
    std::istringstream in{std::string(text)};
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        // A comment starts with '#' at the line start or after a blank ("#ff8800" colours stay).
        for (size_t i = 0; i < line.size(); ++i)
            if (line[i] == '#' && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t')) {
                line.erase(i);
                break;
            }
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        if (out.size() >= kMaxScriptCommands)
            throw InputError(source, "script longer than " + std::to_string(kMaxScriptCommands) + " commands");
        try {
            out.push_back(parse_script_line(line.substr(line.find_first_not_of(" \t"))));
            out.back().line = n;
        } catch (const InputError& e) {
            throw InputError(source + ":" + std::to_string(n) + ": " + e.what());
        }
    }
    return out;
}

std::vector<ScriptCommand> read_script(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "cannot open script");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw InputError(path, "cannot read script");
    return parse_script(text.str(), path);
}

}  // namespace inkshade
