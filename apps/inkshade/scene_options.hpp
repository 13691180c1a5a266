// The command-line options of the scene (inkshade/options.hpp's table): every option a command
// takes becomes a flag with the table's help, and its text fills a SceneRequest (scene.hpp),
// which make_scene checks as it checks every front end's.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "inkshade/options.hpp"
#include "inkshade/scene.hpp"

namespace inkshade::cli {

struct SceneOptions {
    unsigned front = kRender;  // which of the table's options the command takes
    std::string model;
    std::map<std::string, std::string> texts;               // option name -> the text given
    std::map<std::string, std::vector<std::string>> lists;  // the repeatable options' texts
    std::map<std::string, bool> flags;                      // the Flag options

    // The table's options of `front`. MODEL, a positional, only where `model` is true, and then
    // required unless model_required is false (`view` opens a default; `render --scene` names
    // one). `suffix` ends each help line (batch: "where the manifest gives none").
    void add_to(CLI::App& cmd, unsigned front, bool model = true, bool model_required = true,
                const std::string& suffix = {});
    // The request with the given options parsed (InputError naming the option) and, with
    // `scene_file`, a three.js scene's values where `cmd` has no option of its own.
    SceneRequest to_request(const CLI::App& cmd, const std::string& scene_file = {}) const;
};

// The names of a comma-separated option (--lines a,b), or nothing when it is not given.
std::optional<std::vector<std::string>> split_names(const std::string& text);

}  // namespace inkshade::cli
