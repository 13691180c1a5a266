// `inkshade styles`: the shading models and their parameters.
#include <cstdio>

#include "commands.hpp"
#include "inkshade/lines.hpp"
#include "inkshade/shading.hpp"
#include "inkshade/style.hpp"

namespace inkshade::cli {

namespace {

std::string range_text(const ParamSpec& p) {
    if (p.type == ParamType::Choice) {
        std::string c;
        for (const auto& name : p.choices) c += (c.empty() ? "" : "|") + name;
        return "{" + c + "}";
    }
    if (p.type == ParamType::Bool) return "";
    std::string r = "[" + format_number(p.min) + ", " + format_number(p.max) + "]";
    if (p.type == ParamType::FloatList) r += " up to " + std::to_string(p.max_count) + " values";
    return r;
}

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

void print_params(const std::vector<ParamSpec>& params) {
    for (const ParamSpec& p : params)
        std::printf("      %-18s %-6s default %-14s %s  %s\n", p.name.c_str(), type_text(p.type),
                    format_param_value(p, p.default_value).c_str(), range_text(p).c_str(), p.doc.c_str());
}

}  // namespace

Command add_styles_command(CLI::App& app) {
    CLI::App* cmd =
        app.add_subcommand("styles", "list styles, shading models, debug views, line types and their parameters");
    return [cmd] {
        (void)cmd;
        std::printf("Styles (--style NAME, or --style FILE.toml; docs/styles.md):\n");
        for (const std::string& name : builtin_style_names()) {
            Style style = load_style(name);
            std::printf("  %-12s %s  [model %s]\n", name.c_str(), style.description.c_str(),
                        style.shading.model.c_str());
        }
        bool debug_header = false;
        std::printf("\nShading models (--shading NAME, --set [NAME.]param=value):\n");
        for (const ShadingModel* m : shading_models()) {
            if (m->debug_view && !debug_header) {
                std::printf("\nDebug views (--shading NAME):\n");
                debug_header = true;
            }
            std::printf("  %-12s %s\n", m->name.c_str(), m->summary.c_str());
            print_params(m->params);
        }
        std::printf("\nLine types ([[lines]] in a style, --set TYPE.param=value; `lines --lines` for vector ones):\n");
        for (const LineType* t : line_types()) {
            std::printf("  %-12s %s  [%s]\n", t->name.c_str(), t->summary.c_str(),
                        t->space == LineSpace::Image ? "raster" : "vector");
            print_params(t->params);
        }
        return 0;
    };
}

}  // namespace inkshade::cli
