// Style files (TOML, parsed with toml++; text toml++ mishandles is refused first by
// toml_prelexer.hpp). TOML because presets are written and tuned by hand: comments, no quoting
// of keys, arrays for band lists.
#include "inkshade/style.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

#define TOML_EXCEPTIONS 1
#include <toml++/toml.h>

#include "core/embedded_file.hpp"
#include "core/name_suggestion.hpp"
#include "inkshade/color.hpp"
#include "inkshade/error.hpp"
#include "io/atomic_file.hpp"
#include "io/text_scanner.hpp"
#include "styles/line_sets.hpp"
#include "styles/toml_prelexer.hpp"

namespace inkshade {

namespace styles {
const std::vector<EmbeddedFile>& embedded_style_presets();  // generated from src/styles/presets
}

namespace {

constexpr size_t kMaxStyleFileBytes = 1 << 20;  // style files are small; refuse anything huge

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

const EmbeddedFile* embedded_preset(const std::string& name) {
    for (const auto& f : styles::embedded_style_presets())
        if (stem(f.path) == name) return &f;
    return nullptr;
}

glm::vec4 color_value(const toml::node& node, const std::string& source, const std::string& key) {
    try {
        if (auto s = node.value<std::string>()) return parse_color(*s);
        if (auto* arr = node.as_array()) {
            std::string text;
            for (const auto& e : *arr) {
                auto v = e.value<double>();
                if (!v) throw InputError("not a number");
                text += (text.empty() ? "" : ",") + std::to_string(*v);
            }
            return parse_color(text);
        }
        if (auto v = node.value<double>()) return parse_color(std::to_string(*v));
    } catch (const InputError& e) {
        throw InputError(source, key + ": " + e.what());
    }
    throw InputError(source, key + ": expected a colour (\"#rrggbb\", \"r,g,b\" or [r, g, b])");
}

// A parameter value from a TOML node: numbers, booleans, strings (choices, colours, anything
// parse_param_value reads) and arrays of numbers (lists, colours).
ParamValue param_value(const ParamSpec& spec, const toml::node& node, const std::string& source) {
    try {
        if (auto b = node.value_exact<bool>()) return check_param_value(spec, {*b ? 1.0f : 0.0f});
        if (auto s = node.value_exact<std::string>()) return parse_param_value(spec, *s);
        if (auto d = node.value<double>()) return check_param_value(spec, {float(*d)});
        if (auto* arr = node.as_array()) {
            ParamValue v;
            for (const auto& e : *arr) {
                auto d = e.value<double>();
                if (!d) throw InputError("parameter " + spec.name + ": arrays hold numbers only");
                v.push_back(float(*d));
            }
            return check_param_value(spec, v);
        }
    } catch (const InputError& e) {
        throw InputError(source, e.what());
    }
    throw InputError(source, "parameter " + spec.name + ": unsupported value type");
}

void reject_unknown_keys(const toml::table& table, const std::vector<std::string>& allowed, const std::string& source,
                         const std::string& where) {
    for (const auto& [key, node] : table) {
        (void)node;
        if (std::find(allowed.begin(), allowed.end(), std::string(key.str())) == allowed.end()) {
            std::string list;
            for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
            throw InputError(source,
                             "unknown key '" + std::string(key.str()) + "'" + where + " (allowed: " + list + ")");
        }
    }
}

// [light] intensity, decay and distance: three.js's ranges (0 and up) and the threejs-* models'
// limits (intensity and distance up to 1e6 and 1e9, decay up to 16). `key` names it in errors.
void check_light_value(LightValue which, double v, const std::string& key) {
    const double max = which == LightValue::Intensity ? 1e6 : which == LightValue::Decay ? 16.0 : 1e9;
    if (!(v >= 0.0 && v <= max))
        throw InputError(key + ": expected a number in [0, " + format_number(float(max)) + "]");
}

Style model_default_style(const ShadingModel& model) {
    Style s;
    s.name = model.name;
    s.description = model.summary;
    s.shading.model = model.name;
    s.shading.base_color_use = BaseColorUse::Fallback;  // as every style's base colour (white here)
    return s;
}

// A TOML string: toml++'s literal 'text' for plain text; a basic "..." string with escapes
// when the text holds control characters or quotes. toml++ 3.3 writes text with line breaks as
// '''...''' without checking for ''' inside it, which it then cannot read back (found by
// fuzzing: a description holding both).
std::string toml_string(const std::string& s) {
    const bool plain = std::none_of(s.begin(), s.end(), [](char c) {
        return static_cast<unsigned char>(c) < 0x20 || c == 0x7f || c == '\'' || c == '"' || c == '\\';
    });
    if (plain) {
        std::ostringstream out;
        out << toml::value<std::string>(s);
        return out.str();
    }
    std::string out = "\"";
    for (char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            case '\r': out += "\\r"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned char>(c));
                    out += buf;
                } else {
                    out += c;
                }
        }
    }
    return out + "\"";
}

std::string color_text(glm::vec4 c, bool with_alpha = false) {
    std::string s = "\"" + format_number(c.r) + "," + format_number(c.g) + "," + format_number(c.b);
    if (with_alpha) s += "," + format_number(c.a);
    return s + "\"";
}

// One [[lines]] table: type = "NAME" and that type's parameters.
LineSettings parse_line_settings(const toml::table& table, const std::string& source) {
    auto type_name = table["type"].value<std::string>();
    if (!type_name) throw InputError(source, "every [[lines]] table needs type = \"NAME\"");
    const LineType* type = nullptr;
    try {
        type = &line_type(*type_name);
    } catch (const InputError& e) {
        throw InputError(source, e.what());
    }
    LineSettings settings{type->name, {}};
    for (const auto& [key, node] : table) {
        const std::string k(key.str());
        if (k == "type") continue;
        const ParamSpec* spec = type->param(k);
        if (!spec) {
            std::string names;
            for (const auto& p : type->params) names += (names.empty() ? "" : ", ") + p.name;
            throw InputError(source,
                             "line type '" + type->name + "' has no parameter '" + k + "' (it has " + names + ")");
        }
        settings.params[spec->name] = param_value(*spec, node, source);
    }
    return settings;
}

// `name = value  # doc` for every parameter, values written as parse_style reads them.
void write_params(std::ostream& out, const std::vector<ParamSpec>& params, const ParamValues& values) {
    for (const ParamSpec& p : params) {
        const ParamValue& v = value_or_default(p, values);
        out << p.name << " = ";
        switch (p.type) {
            case ParamType::Bool: out << (v.at(0) != 0.0f ? "true" : "false"); break;
            case ParamType::Float:
            case ParamType::Int: out << format_param_value(p, v); break;
            case ParamType::FloatList: out << "[" << format_param_value(p, v) << "]"; break;
            case ParamType::Choice:
            case ParamType::Color: out << toml_string(format_param_value(p, v)); break;
        }
        out << "  # " << p.doc << "\n";
    }
}

// Error messages quote keys and values from the file or the --set text, which may hold line
// breaks and other control characters ("a\r" is a valid TOML key; found by fuzzing): those
// become '?', so every error stays one line.
InputError one_line_error(const InputError& e) { return InputError(io::one_line(e.what())); }

void apply_override_unchecked(Style& style, const std::string& text) {
    const size_t eq = text.find('=');
    if (eq == std::string::npos) throw InputError("expected [model.]param=value or linetype.param=value");
    std::string key = text.substr(0, eq);
    const std::string value = text.substr(eq + 1);
    const ShadingModel& model = shading_model(style.shading.model);
    const std::vector<ParamSpec>* params = &model.params;
    std::string owner = "model '" + model.name + "'";
    const LineType* line = nullptr;
    if (size_t dot = key.find('.'); dot != std::string::npos) {
        const std::string prefix = key.substr(0, dot);
        key = key.substr(dot + 1);
        if (!equal_ignoring_case(prefix, model.name)) {
            for (const LineType* t : line_types())
                if (equal_ignoring_case(t->name, prefix)) line = t;
            if (!line)
                throw InputError("parameter is for model '" + prefix + "' but the shading model is '" + model.name +
                                 "' (and there is no line type '" + prefix + "')");
            params = &line->params;
            owner = "line type '" + line->name + "'";
        }
    }
    const ParamSpec* spec = find_param(*params, key);
    if (!spec) {
        std::string names;
        for (const auto& p : *params) names += (names.empty() ? "" : ", ") + p.name;
        throw InputError(owner + " has no parameter '" + key + "'" +
                         (names.empty() ? " (it has none)" : " (it has " + names + ")"));
    }
    ParamValue v = parse_param_value(*spec, value);
    if (!line) {
        style.shading.params[spec->name] = std::move(v);
        return;
    }
    // Every line of the type, in the style's own [[lines]] and in every line set.
    std::string drawn;
    bool found = false;
    for (LineSettings& l : style.lines) {
        if (l.type == line->name) {
            l.params[spec->name] = v;
            found = true;
        }
        drawn += (drawn.empty() ? "" : ", ") + l.type;
    }
    if (found) return;
    throw InputError("the style draws no '" + line->name + "' lines (" +
                     (drawn.empty() ? std::string("it draws none") : "it draws " + drawn) + ")");
}

// The top-level keys: description, background, base-color, smooth-angle, up-axis, mesh-colors,
// line-unit.
void parse_top_level(const toml::table& root, const std::string& source, Style& style) {
    if (auto d = root["description"].value<std::string>()) style.description = *d;
    if (auto* n = root.get("background")) style.background = color_value(*n, source, "background");
    // A style's base colour tints only meshes without colours of their own (a preset's skin
    // tone must not darken a textured model); mesh-colors = false fills with it alone (ink).
    style.shading.base_color_use = BaseColorUse::Fallback;
    if (auto* n = root.get("base-color")) style.shading.base_color = glm::vec3(color_value(*n, source, "base-color"));
    if (auto* n = root.get("smooth-angle")) {
        const std::optional<double> angle = n->value<double>();
        if (!angle || !(*angle >= 0.0 && *angle <= 180.0))
            throw InputError(source, "smooth-angle: expected degrees in [0, 180]");
        style.smooth_angle = float(*angle);
    }
    if (auto* n = root.get("up-axis")) {
        const std::optional<std::string> name = n->value<std::string>();
        style.up_axis = name ? up_axis_named(*name) : std::nullopt;
        if (!style.up_axis) throw InputError(source, "up-axis: expected \"x\", \"y\", \"z\", \"-x\", \"-y\" or \"-z\"");
    }
    if (auto* n = root.get("mesh-colors")) {
        const std::optional<bool> use = n->value_exact<bool>();
        if (!use) throw InputError(source, "mesh-colors: expected true or false");
        if (!*use) style.shading.base_color_use = BaseColorUse::Only;
    }
    if (auto* n = root.get("line-unit")) {
        const std::optional<std::string> unit = n->value<std::string>();
        if (!unit || (*unit != "px" && *unit != "mm")) throw InputError(source, "line-unit: expected \"px\" or \"mm\"");
        style.lines_in_mm = *unit == "mm";
    }
}

// The optional [light] table.
void parse_light(const toml::table& root, const std::string& source, Style& style) {
    if (auto* light = root["light"].as_table()) {
        reject_unknown_keys(*light, {"color", "ambient", "intensity", "decay", "distance"}, source, " in [light]");
        if (auto* n = light->get("color")) style.light_color = glm::vec3(color_value(*n, source, "light.color"));
        if (auto* n = light->get("ambient")) style.ambient = glm::vec3(color_value(*n, source, "light.ambient"));
        const std::pair<const char*, LightValue> values[] = {
            {"intensity", LightValue::Intensity}, {"decay", LightValue::Decay}, {"distance", LightValue::Distance}};
        for (const auto& [key, which] : values)
            if (auto* n = light->get(key)) {
                const std::optional<double> v = n->value<double>();
                try {
                    check_light_value(which, v.value_or(-1.0), key);
                } catch (const InputError& e) {
                    throw InputError(source, std::string("light.") + e.what());
                }
                (which == LightValue::Intensity ? style.light_intensity
                 : which == LightValue::Decay   ? style.light_decay
                                                : style.light_distance) = float(*v);
            }
    } else if (root.contains("light")) {
        throw InputError(source, "[light] must be a table");
    }
}

// The [shading] table: the model and its parameters.
void parse_shading(const toml::table& root, const std::string& source, Style& style) {
    auto* shading = root["shading"].as_table();
    if (!shading) throw InputError(source, "missing [shading] table with a model");
    auto model_name = (*shading)["model"].value<std::string>();
    if (!model_name) throw InputError(source, "[shading] needs model = \"NAME\"");
    const ShadingModel* model = nullptr;
    try {
        model = &shading_model(*model_name);
    } catch (const InputError& e) {
        throw InputError(source, e.what());
    }
    style.shading.model = model->name;
    for (const auto& [key, node] : *shading) {
        const std::string k(key.str());
        if (k == "model") continue;
        const ParamSpec* spec = model->param(k);
        if (!spec) {
            std::string names;
            for (const auto& p : model->params) names += (names.empty() ? "" : ", ") + p.name;
            throw InputError(source, "model '" + model->name + "' has no parameter '" + k + "'" +
                                         (names.empty() ? " (it has none)" : " (it has " + names + ")"));
        }
        style.shading.params[spec->name] = param_value(*spec, node, source);
    }
}

// The optional [[lines]] tables, each line type once.
void parse_lines(const toml::table& root, const std::string& source, Style& style) {
    if (auto* lines = root["lines"].as_array()) {
        for (const auto& entry : *lines) {
            const toml::table* table = entry.as_table();
            if (!table) throw InputError(source, "lines must be an array of tables ([[lines]])");
            style.lines.push_back(parse_line_settings(*table, source));
            for (size_t i = 0; i + 1 < style.lines.size(); ++i)
                if (style.lines[i].type == style.lines.back().type)
                    throw InputError(source, "line type '" + style.lines.back().type + "' is listed twice");
        }
    } else if (root.contains("lines")) {
        throw InputError(source, "lines must be an array of tables ([[lines]])");
    }
}

Style parse_style_unchecked(std::string_view text, const std::string& source) {
    if (text.size() > kMaxStyleFileBytes) throw InputError(source, "style file larger than 1 MiB");
    styles::check_toml_text(text, source);
    toml::table root;
    try {
        root = toml::parse(text, source);
    } catch (const toml::parse_error& e) {
        std::string what(e.description());
        std::replace(what.begin(), what.end(), '\n', ' ');
        throw InputError(source, "line " + std::to_string(e.source().begin.line) + ": " + what);
    }
    reject_unknown_keys(root,
                        {"description", "background", "base-color", "mesh-colors", "smooth-angle", "up-axis", "line-unit",
                         "light", "shading", "lines", "lineset"},
                        source, "");
    Style style;
    style.name = stem(source);
    parse_top_level(root, source, style);
    parse_light(root, source, style);
    parse_shading(root, source, style);
    parse_lines(root, source, style);
    styles::parse_line_sets(
        root, source, style.lines, [&](const toml::table& t) { return parse_line_settings(t, source); },
        [&](const ParamSpec& spec, const toml::node& node) { return param_value(spec, node, source); });
    styles::check_image_space_lines(style.lines, source);
    return style;
}

// The built-in style `name` (a preset, else a shading model's defaults), spelt exactly.
std::optional<Style> builtin_style(const std::string& name) {
    if (const EmbeddedFile* f = embedded_preset(name)) {
        Style s = parse_style(f->contents, std::string("builtin style ") + name);
        s.name = name;
        return s;
    }
    for (const ShadingModel* m : shading_models())
        if (m->name == name) return model_default_style(*m);
    return std::nullopt;
}

}  // namespace

void apply_style_light(const Style& style, Light& light) {
    if (style.light_color) light.color = *style.light_color;
    if (style.ambient) light.ambient = *style.ambient;
    if (style.light_intensity) light.intensity = *style.light_intensity;
    if (style.light_decay) light.decay = *style.light_decay;
    if (style.light_distance) light.range = *style.light_distance;
}

const char* light_value_param(LightValue which) {
    switch (which) {
        case LightValue::Intensity: return "light-intensity";
        case LightValue::Decay: return "light-decay";
        case LightValue::Distance: return "light-distance";
    }
    return "";
}

void set_light_value(Style& style, LightValue which, float value) {
    const char* name = light_value_param(which);
    if (const ParamSpec* spec = shading_model(style.shading.model).param(name)) {
        style.shading.params[name] = check_param_value(*spec, {value});
        return;
    }
    check_light_value(which, double(value), name);
    (which == LightValue::Intensity ? style.light_intensity
     : which == LightValue::Decay   ? style.light_decay
                                    : style.light_distance) = value;
}

std::optional<float> light_value(const Style& style, LightValue which) {
    const char* name = light_value_param(which);
    if (shading_model(style.shading.model).param(name)) {
        auto it = style.shading.params.find(name);
        return it != style.shading.params.end() && it->second.size() == 1 ? std::optional(it->second[0]) : std::nullopt;
    }
    return which == LightValue::Intensity ? style.light_intensity
           : which == LightValue::Decay   ? style.light_decay
                                          : style.light_distance;
}

void apply_override(Style& style, const std::string& text) {
    try {
        apply_override_unchecked(style, text);
    } catch (const InputError& e) {
        throw one_line_error(e);
    }
}

Style parse_style(std::string_view text, const std::string& source) {
    try {
        return parse_style_unchecked(text, source);
    } catch (const InputError& e) {
        throw one_line_error(e);
    }
}

Style load_style(const std::string& name_or_path) {
    if (auto s = builtin_style(name_or_path)) return *s;

    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(name_or_path, ec)) {
        // Built-in names are matched ignoring case, after files: a path stays a path.
        if (auto s = builtin_style(lower_ascii(name_or_path))) return *s;
        const std::vector<std::string> builtin = builtin_style_names();
        std::string names;
        for (const auto& n : builtin) names += (names.empty() ? "" : ", ") + n;
        throw InputError(name_or_path, "no such style file or built-in style (built-in: " + names + ")" +
                                           did_you_mean(name_or_path, builtin));
    }
    if (!fs::is_regular_file(name_or_path, ec)) throw InputError(name_or_path, "not a regular file");
    if (fs::file_size(name_or_path, ec) > kMaxStyleFileBytes)
        throw InputError(name_or_path, "style file larger than 1 MiB");
    std::ifstream in(name_or_path, std::ios::binary);
    if (!in) throw InputError(name_or_path, "cannot open file");
    std::stringstream ss;
    ss << in.rdbuf();
    return parse_style(ss.str(), name_or_path);
}

std::string format_style(const Style& style) {
    const ShadingModel& model = shading_model(style.shading.model);
    std::ostringstream out;
    out << "# Inkshade style " << style.name << " (TOML; see docs/styles.md)\n";
    out << "description = " << toml_string(style.description) << "\n";
    out << "background = " << color_text(style.background, style.background.a < 1.0f) << "\n";
    out << "base-color = " << color_text(glm::vec4(style.shading.base_color, 1.0f)) << "\n";
    if (style.smooth_angle) out << "smooth-angle = " << format_number(*style.smooth_angle) << "\n";
    if (style.up_axis) out << "up-axis = " << toml_string(up_axis_name(*style.up_axis)) << "\n";
    if (style.shading.base_color_use == BaseColorUse::Only) out << "mesh-colors = false\n";
    if (style.lines_in_mm) out << "line-unit = \"mm\"\n";
    if (style.light_color || style.ambient || style.light_intensity || style.light_decay || style.light_distance) {
        out << "\n[light]\n";
        if (style.light_color) out << "color = " << color_text(glm::vec4(*style.light_color, 1.0f)) << "\n";
        if (style.ambient) out << "ambient = " << color_text(glm::vec4(*style.ambient, 1.0f)) << "\n";
        if (style.light_intensity) out << "intensity = " << format_number(*style.light_intensity) << "\n";
        if (style.light_decay) out << "decay = " << format_number(*style.light_decay) << "\n";
        if (style.light_distance) out << "distance = " << format_number(*style.light_distance) << "\n";
    }
    out << "\n[shading]\nmodel = " << toml_string(model.name) << "\n";
    write_params(out, model.params, style.shading.params);
    for (const LineSettings& l : style.lines) {
        if (!l.lineset.empty()) continue;
        out << "\n[[lines]]\ntype = " << toml_string(l.type) << "\n";
        write_params(out, line_type(l.type).params, l.params);
    }
    styles::write_line_sets(out, style.lines, toml_string, [](std::ostream& o, const LineSettings& l) {
        write_params(o, line_type(l.type).params, l.params);
    });
    return out.str();
}

void save_style(const std::string& path, const Style& style) { io::write_file_atomic(path, format_style(style)); }

Style shading_model_style(const std::string& model_name) { return model_default_style(shading_model(model_name)); }

std::vector<std::string> builtin_style_names() {
    std::vector<std::string> names;
    for (const auto& f : styles::embedded_style_presets()) names.push_back(stem(f.path));
    for (const ShadingModel* m : shading_models())
        if (std::find(names.begin(), names.end(), m->name) == names.end()) names.push_back(m->name);
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace inkshade
