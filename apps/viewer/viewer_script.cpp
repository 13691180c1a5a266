#include "viewer_script.hpp"

#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "style_keys.hpp"

namespace inkshade::viewer {

void check_script(const std::vector<ScriptCommand>& commands, const Scene& scene, const std::string& path) {
    Style style = scene.style;
    for (const ScriptCommand& c : commands) {
        try {
            if (c.kind == ScriptCommand::Set)
                apply_set(style, c.argument);
            else if (c.kind == ScriptCommand::StyleName)
                style = load_style(c.argument);
            else if (c.kind == ScriptCommand::Key && c.count == 'F')
                style = next_shading_model_style(style);
            else if (c.kind == ScriptCommand::Key && c.count >= '1' && c.count <= '9')
                toggle_line_type(style, size_t(c.count - '1'));
            else if (c.kind == ScriptCommand::Open)
                Scene(scene).apply_file_scene(load_mesh(c.argument, scene.load_options()));
        } catch (const InputError& e) {
            throw InputError(path + ":" + std::to_string(c.line) + ": " + e.what());
        }
    }
}

void apply_set(Style& style, const std::string& text) {
    try {
        apply_override(style, text);
    } catch (const InputError& e) {
        throw InputError("set " + text + ": " + e.what());
    }
}

}  // namespace inkshade::viewer
