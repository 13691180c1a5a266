// The command-line options of the commands that render (render, lines, view): model, style,
// camera, light, image. They fill a SceneRequest (inkshade/scene.hpp), which make_scene checks
// as it checks every front end's.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "inkshade/scene.hpp"

namespace inkshade::cli {

struct SceneOptions {
    SceneRequest request;  // the options with typed values are bound to it directly
    // Options given as text, parsed by to_request().
    std::string size = "1024x1024";
    std::string eye, target, up, up_axis;
    std::string light_pos, light_target, light_type = "directional", light_color, ambient, base_color, background;
    std::string lights = "style";
    std::vector<std::string> morphs, expressions;  // NAME=W each

    // MODEL is a required positional unless model_required is false (`view` opens a default).
    void add_to(CLI::App& cmd, bool model_required = true);
    // The request with the text options parsed (InputError naming the option) and, with
    // `scene_file`, a three.js scene's values where `cmd` has no option of its own.
    SceneRequest to_request(const CLI::App& cmd, const std::string& scene_file = {}) const;
};

// The names of a comma-separated option (--lines a,b), or nothing when it is not given.
std::optional<std::vector<std::string>> split_names(const std::string& text);

}  // namespace inkshade::cli
