// `inkshade styles`: the shading models and their parameters.
#include <cstdio>

#include "commands.hpp"
#include "inkshade/shading.hpp"

namespace inkshade::cli {

namespace {

const char* type_text(ParamType t) {
    switch (t) {
        case ParamType::Float: return "float";
        case ParamType::Int: return "int";
        case ParamType::Bool: return "bool";
        case ParamType::Color: return "colour";
        case ParamType::Choice: return "choice";
        case ParamType::FloatList: return "list";
    }
    return "?";
}

}  // namespace

Command add_styles_command(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("styles", "list shading models, debug views and their parameters");
    return [cmd] {
        (void)cmd;
        bool debug_header = false;
        std::printf("Shading models (--shading NAME, --set NAME.param=value):\n");
        for (const ShadingModel* m : shading_models()) {
            if (m->debug_view && !debug_header) {
                std::printf("\nDebug views (--shading NAME):\n");
                debug_header = true;
            }
            std::printf("  %-12s %s\n", m->name.c_str(), m->summary.c_str());
            for (const ParamSpec& p : m->params)
                std::printf("      %-12s %-6s default %-12s range [%g, %g]  %s\n", p.name.c_str(), type_text(p.type),
                            format_param_value(p, p.default_value).c_str(), p.min, p.max, p.doc.c_str());
        }
        return 0;
    };
}

}  // namespace inkshade::cli
