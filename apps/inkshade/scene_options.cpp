#include "scene_options.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "inkshade/io.hpp"

namespace inkshade::cli {

namespace {

bool repeatable(const OptionSpec& spec) {
    return spec.kind == OptionKind::Weights || spec.kind == OptionKind::Overrides;
}

// CLI11 gives an option the next argument whatever it is: `--time -o out.png` would read "-o"
// as the time and then miss -o. An argument that looks like an option is refused as a value,
// unless it is one of the option's choices (--up-axis -z) or a number.
CLI::Validator not_an_option(const OptionSpec& spec) {
    return CLI::Validator(
        [&spec](std::string& v) -> std::string {
            const bool dash_letter = v.size() >= 2 && v[0] == '-' && (std::isalpha((unsigned char)v[1]) || v[1] == '-');
            const bool choice = std::find(spec.choices.begin(), spec.choices.end(), v) != spec.choices.end();
            if (!dash_letter || choice || v == "-inf" || v == "-nan") return {};
            return "expected a value, got the option " + v;
        },
        "", "value");
}

}  // namespace

void SceneOptions::add_to(CLI::App& cmd, unsigned which, bool model_positional, bool model_required,
                          const std::string& suffix) {
    front = which;
    if (model_positional)
        cmd.add_option("MODEL", model,
                       "mesh file (" + readable_extensions() + ") or builtin:sphere|torus|torus-knot|teapot")
            ->required(model_required);
    for (const OptionSpec& spec : scene_options()) {
        if (!spec.takes(front)) continue;
        // The default in the help line, where the help does not say it in words already.
        const std::string d = option_default(spec, front);
        const bool said = spec.help.find("default") != std::string::npos;
        const std::string flag = "--" + spec.name,
                          help = spec.help + (d.empty() || said || spec.kind == OptionKind::Flag ? "" : " (default " + d + ")") + suffix;
        if (spec.kind == OptionKind::Flag) {
            cmd.add_flag(flag, flags[spec.name], help);
            continue;
        }
        // One value per occurrence, so MODEL may follow; only repeatable options may recur.
        CLI::Option* option = repeatable(spec) ? cmd.add_option(flag, lists[spec.name], help)->allow_extra_args(false)
                                               : cmd.add_option(flag, texts[spec.name], help);
        option->option_text(spec.value)->check(not_an_option(spec));
    }
}

std::optional<std::vector<std::string>> split_names(const std::string& text) {
    if (text.empty()) return std::nullopt;
    std::vector<std::string> names;
    std::stringstream ss(text);
    for (std::string name; std::getline(ss, name, ',');) names.push_back(name);
    return names;
}

SceneRequest SceneOptions::to_request(const CLI::App& cmd, const std::string& scene_file) const {
    SceneRequest r = default_request(front);
    r.model = model;
    for (const OptionSpec& spec : scene_options()) {
        if (!spec.takes(front)) continue;
        if (spec.kind == OptionKind::Flag) {
            if (flags.at(spec.name)) spec.put(r, true);
            continue;
        }
        if (cmd.count("--" + spec.name) == 0) continue;
        if (repeatable(spec))
            for (const std::string& text : lists.at(spec.name)) set_option(r, spec, text);
        else
            set_option(r, spec, texts.at(spec.name));
    }
    // Without --size a file camera's aspect ratio decides; a batch job's image keeps its size.
    r.size_from_camera = front != kBatch && cmd.count("--size") == 0;
    if (!scene_file.empty())
        apply_threejs_scene(scene_file, r, [&](const std::string& option) {
            return cmd.count(option == "model" ? "MODEL" : "--" + option) > 0;
        });
    return r;
}

}  // namespace inkshade::cli
