// Parameter constructors, parsing, range checks and formatting (inkshade/params.hpp).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "inkshade/color.hpp"
#include "inkshade/error.hpp"
#include "inkshade/params.hpp"

namespace inkshade {

namespace {

std::string range_text(const ParamSpec& s) { return "[" + format_number(s.min) + ", " + format_number(s.max) + "]"; }

[[noreturn]] void fail(const ParamSpec& spec, const std::string& why) {
    throw InputError("parameter " + spec.name + ": " + why);
}

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> parts;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, sep)) parts.push_back(item);
    if (!text.empty() && text.back() == sep) parts.push_back("");
    return parts;
}

float parse_number(const ParamSpec& spec, std::string text) {
    while (!text.empty() && text.front() == ' ') text.erase(text.begin());
    while (!text.empty() && text.back() == ' ') text.pop_back();
    double v = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v))
        fail(spec, "'" + text + "' is not a number");
    return float(v);
}

}  // namespace

std::string format_number(float v) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);  // shortest text that reads back exactly
    return ec == std::errc() ? std::string(buf, end) : "nan";
}

ParamSpec float_param(std::string name, float value, float min, float max, std::string doc) {
    return {std::move(name), ParamType::Float, {value}, min, max, std::move(doc)};
}
ParamSpec int_param(std::string name, int value, int min, int max, std::string doc) {
    return {std::move(name), ParamType::Int, {float(value)}, float(min), float(max), std::move(doc)};
}
ParamSpec bool_param(std::string name, bool value, std::string doc) {
    return {std::move(name), ParamType::Bool, {value ? 1.0f : 0.0f}, 0.0f, 1.0f, std::move(doc)};
}
ParamSpec color_param(std::string name, glm::vec3 value, std::string doc) {
    return {std::move(name), ParamType::Color, {value.r, value.g, value.b}, 0.0f, 1.0f, std::move(doc)};
}
ParamSpec srgb_color_param(std::string name, glm::vec3 value, std::string doc) {
    ParamSpec spec = color_param(std::move(name), value, std::move(doc));
    spec.srgb = true;
    return spec;
}
ParamSpec choice_param(std::string name, std::vector<std::string> choices, int value, std::string doc) {
    float max = float(choices.size()) - 1.0f;
    return {std::move(name), ParamType::Choice, {float(value)}, 0.0f, max, std::move(doc), std::move(choices)};
}
ParamSpec list_param(std::string name, std::vector<float> values, int max_count, float min, float max,
                     std::string doc) {
    return {std::move(name), ParamType::FloatList, std::move(values), min, max, std::move(doc), {}, max_count};
}

const ParamValue& value_or_default(const ParamSpec& spec, const ParamValues& values) {
    auto it = values.find(spec.name);
    return it != values.end() ? it->second : spec.default_value;
}

const ParamSpec* find_param(const std::vector<ParamSpec>& params, const std::string& name) {
    for (const ParamSpec& p : params)
        if (p.name == name) return &p;
    return nullptr;
}

ParamSpec compile_time(ParamSpec spec) {
    spec.compile_time = true;
    return spec;
}

ParamValue check_param_value(const ParamSpec& spec, const ParamValue& value) {
    size_t want = spec.type == ParamType::Color ? 3 : 1;
    if (spec.type == ParamType::Color && value.size() == 4) {
        ParamValue rgb(value.begin(), value.begin() + 3);  // alpha is ignored
        return check_param_value(spec, rgb);
    }
    if (spec.type == ParamType::FloatList) {
        if (value.empty() || value.size() > size_t(spec.max_count))
            fail(spec, "needs 1 to " + std::to_string(spec.max_count) + " values, got " + std::to_string(value.size()));
    } else if (value.size() != want) {
        fail(spec, "needs " + std::to_string(want) + (want == 1 ? " value" : " values") + ", got " +
                       std::to_string(value.size()));
    }
    for (float v : value) {
        if (!std::isfinite(v)) fail(spec, "value is not finite");
        if (v < spec.min || v > spec.max) fail(spec, format_number(v) + " is outside " + range_text(spec));
        if ((spec.type == ParamType::Int || spec.type == ParamType::Bool || spec.type == ParamType::Choice) &&
            v != std::floor(v))
            fail(spec, format_number(v) + " is not an integer");
    }
    return value;
}

ParamValue parse_param_value(const ParamSpec& spec, const std::string& text) {
    switch (spec.type) {
        case ParamType::Color: {
            glm::vec4 c;
            try {
                c = parse_color(text);
            } catch (const InputError& e) {
                fail(spec, e.what());
            }
            return {c.r, c.g, c.b};
        }
        case ParamType::Bool:
            if (text == "true" || text == "1" || text == "on" || text == "yes") return {1.0f};
            if (text == "false" || text == "0" || text == "off" || text == "no") return {0.0f};
            fail(spec, "'" + text + "' is not a boolean (true/false)");
        case ParamType::Choice: {
            for (size_t i = 0; i < spec.choices.size(); ++i)
                if (spec.choices[i] == text) return {float(i)};
            std::string names;
            for (const auto& c : spec.choices) names += (names.empty() ? "" : ", ") + c;
            fail(spec, "'" + text + "' is not one of " + names);
        }
        case ParamType::FloatList: {
            ParamValue v;
            for (const std::string& part : split(text, ',')) v.push_back(parse_number(spec, part));
            return check_param_value(spec, v);
        }
        case ParamType::Float:
        case ParamType::Int: break;
    }
    return check_param_value(spec, {parse_number(spec, text)});
}

std::string format_param_value(const ParamSpec& spec, const ParamValue& value) {
    if (spec.type == ParamType::Bool) return !value.empty() && value[0] != 0.0f ? "true" : "false";
    if (spec.type == ParamType::Choice) {
        size_t i = value.empty() ? 0 : size_t(value[0]);
        return i < spec.choices.size() ? spec.choices[i] : "?";
    }
    std::string out;
    for (float v : value) out += (out.empty() ? "" : ",") + format_number(v);
    return out;
}

}  // namespace inkshade
