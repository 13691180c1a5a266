// Option values as text and back, and their checks (inkshade/options.hpp): one parser per kind
// of value, so every option of a kind reads and fails the same way on every front end.
#include <charconv>
#include <cmath>
#include <cstdio>

#include "inkshade/color.hpp"
#include "inkshade/error.hpp"
#include "inkshade/options.hpp"
#include "io/text_scanner.hpp"
#include "scene/option_name.hpp"

namespace inkshade {

namespace {

// The shortest text that reads back to the same float.
std::string shortest(float v) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : std::to_string(v);
}

std::string join(const std::vector<std::string>& items, const char* separator) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
    return out;
}

// "a, b or c".
std::string either(const std::vector<std::string>& choices) {
    std::string out;
    for (size_t i = 0; i < choices.size(); ++i)
        out += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
    return out;
}

// The option's unit as errors name it: "degrees", "seconds", or "a number".
std::string unit_of(const OptionSpec& s) {
    return s.unit.empty() ? std::string(s.kind == OptionKind::Integer ? "an integer" : "a number") : s.unit;
}

// "degrees in (0, 180)", "seconds >= 0", "1..16" (an integer's range).
std::string range_text(const OptionSpec& s) {
    auto bound = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", v);
        return std::string(buf);
    };
    if (std::isinf(s.max)) return unit_of(s) + (s.min_open ? " > " : " >= ") + bound(s.min);
    if (s.kind == OptionKind::Integer) return bound(s.min) + ".." + bound(s.max);
    return unit_of(s) + " in " + (s.min_open ? "(" : "[") + bound(s.min) + ", " + bound(s.max) +
           (s.max_open ? ")" : "]");
}

double parse_number(const std::string& label, const OptionSpec& s, const std::string& text) {
    double v = 0.0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size() || (s.kind == OptionKind::Integer && v != std::floor(v)))
        throw InputError(label + ": expected " + unit_of(s) + ", got " + io::quote_token(text));
    if (!std::isfinite(v))  // nan, inf: a number, but out of every range
        throw InputError(label + ": expected " + (s.has_range() ? range_text(s) : "a finite number") + ", got " +
                         io::quote_token(text));
    return v;
}

OptionValue parse_text(const OptionSpec& s, const std::string& label, const std::string& text) {
    switch (s.kind) {
        case OptionKind::Number: return io::to_float(parse_number(label, s, text));
        case OptionKind::Integer: {
            const double v = parse_number(label, s, text);
            if (!(std::fabs(v) < 2e9)) throw InputError(label + ": expected an integer, got " + io::quote_token(text));
            return int(v);
        }
        case OptionKind::Flag:
            if (text == "true" || text == "1" || text == "yes") return true;
            if (text == "false" || text == "0" || text == "no") return false;
            throw InputError(label + ": expected true or false, got " + io::quote_token(text));
        case OptionKind::Text: return text;
        case OptionKind::Choice:
            for (const std::string& c : s.choices)
                if (c == text) return text;
            throw InputError(label + ": expected " + either(s.choices) + ", got " + io::quote_token(text));
        case OptionKind::Vector: return parse_vec3(label, text);
        case OptionKind::Color: return parse_color(label, text);
        case OptionKind::Size: return parse_image_size(label, text);
        case OptionKind::Names: {
            const std::vector<std::string> names = split_option_list(text);
            if (names.empty()) throw InputError(label + ": no name given");
            return names;
        }
        case OptionKind::Weights: return parse_named_weights(label, text);
        case OptionKind::Levels: return parse_occlusion_levels(text);  // its message names it
        case OptionKind::Overrides: return std::vector<std::string>{text};
    }
    return {};
}

}  // namespace

const OptionSpec* find_option(std::string_view name) {
    for (const OptionSpec& s : scene_options()) {
        if (s.name == name) return &s;
        std::string keyword = s.name;
        for (char& c : keyword)
            if (c == '-') c = '_';
        if (keyword == name) return &s;
    }
    return nullptr;
}

SceneRequest default_request(unsigned front) {
    SceneRequest r;
    if (front & (kBatch | kPython)) r.size = {512, 512};  // a dataset's images are many
    return r;
}

std::string option_label(const OptionSpec& spec, OptionNames names) { return option_name(names, spec.name); }

OptionValue parse_option(const OptionSpec& spec, const std::string& text, OptionNames names) {
    const std::string label = option_label(spec, names);
    if (text.empty()) throw InputError(label + ": empty value");
    OptionValue value = parse_text(spec, label, text);
    check_option_value(spec, value, names, &text);
    return value;
}

void check_option_value(const OptionSpec& s, const OptionValue& value, OptionNames names, const std::string* text) {
    const std::string label = option_label(s, names);
    double v = 0.0;
    if (const float* f = std::get_if<float>(&value))
        v = *f;
    else if (const int* i = std::get_if<int>(&value))
        v = *i;
    else
        return;
    // What the value was: the text as given, an integer as it is; a float from a program is not
    // repeated (its digits would not be what the caller wrote).
    const std::string got = s.kind == OptionKind::Integer ? ", got " + std::to_string(int(v))
                            : text                         ? ", got " + io::quote_token(*text)
                                                           : std::string();
    if (s.kind == OptionKind::Integer && !s.choices.empty()) {
        for (const std::string& c : s.choices)
            if (c == std::to_string(int(v))) return;
        throw InputError(label + ": expected " + either(s.choices) + got);
    }
    if (!s.has_range()) return;
    const bool below = s.min_open ? !(v > s.min) : !(v >= s.min);
    const bool above = s.max_open ? !(v < s.max) : !(v <= s.max);
    if (below || above) throw InputError(label + ": expected " + range_text(s) + got);
}

void check_option_values(const SceneRequest& request) {
    for (const OptionSpec& s : scene_options()) check_option_value(s, s.get(request), request.names);
}

void set_option(SceneRequest& request, const OptionSpec& spec, const std::string& text) {
    spec.put(request, parse_option(spec, text, request.names));
}

void replace_option(SceneRequest& request, const OptionSpec& spec, const std::string& text, OptionNames names) {
    const OptionValue value = parse_option(spec, text, names);
    spec.put(request, std::monostate{});
    spec.put(request, value);
}

std::string format_option(const OptionSpec& spec, const OptionValue& value) {
    struct Format {
        const OptionSpec& spec;
        std::string operator()(std::monostate) const { return {}; }
        std::string operator()(float v) const { return shortest(v); }
        std::string operator()(int v) const { return std::to_string(v); }
        std::string operator()(bool v) const { return v ? "true" : "false"; }
        std::string operator()(const std::string& v) const { return v; }
        std::string operator()(const glm::vec3& v) const {
            return shortest(v.x) + "," + shortest(v.y) + "," + shortest(v.z);
        }
        std::string operator()(const glm::vec4& v) const {
            return shortest(v.x) + "," + shortest(v.y) + "," + shortest(v.z) +
                   (v.w != 1.0f ? "," + shortest(v.w) : std::string());
        }
        std::string operator()(const glm::ivec2& v) const { return std::to_string(v.x) + "x" + std::to_string(v.y); }
        std::string operator()(const std::vector<std::string>& v) const {
            return join(v, spec.kind == OptionKind::Overrides ? " " : ",");
        }
        std::string operator()(const std::vector<NamedWeight>& v) const {
            std::vector<std::string> items;
            for (const NamedWeight& w : v) items.push_back(w.name + "=" + shortest(w.weight));
            return join(items, ";");
        }
        std::string operator()(const OcclusionLevels& v) const {
            return std::to_string(v.min) + "-" + std::to_string(v.max);
        }
    };
    return std::visit(Format{spec}, value);
}

bool option_is_set(const OptionSpec& spec, const SceneRequest& request) {
    static const SceneRequest defaults;
    const OptionValue value = spec.get(request);
    return !std::holds_alternative<std::monostate>(value) && value != spec.get(defaults);
}

std::vector<std::string> split_option_list(const std::string& text) {
    std::vector<std::string> items;
    std::string item;
    for (char c : text + ",") {
        if (c == ',' || c == ';') {
            const size_t b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
            if (b != std::string::npos) items.push_back(item.substr(b, e - b + 1));
            item.clear();
        } else {
            item += c;
        }
    }
    return items;
}

std::string option_default(const OptionSpec& spec, unsigned front) {
    return format_option(spec, spec.get(default_request(front)));
}

std::string format_option_hash(const OptionSpec& spec, const OptionValue& value) {
    if (spec.hash_text) return spec.hash_text(value);
    if (const float* f = std::get_if<float>(&value)) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.9g", double(*f));  // round-trips every float
        return buf;
    }
    if (const auto* names = std::get_if<std::vector<std::string>>(&value)) return join(*names, ",");
    return format_option(spec, value);
}

}  // namespace inkshade
