#include "inkshade/color.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "core/name_suggestion.hpp"
#include "inkshade/error.hpp"

namespace inkshade {

namespace {

const std::map<std::string, glm::vec4>& color_names() {
    static const std::map<std::string, glm::vec4> names = {
        {"black", {0, 0, 0, 1}},         {"white", {1, 1, 1, 1}},     {"grey", {0.5f, 0.5f, 0.5f, 1}},
        {"gray", {0.5f, 0.5f, 0.5f, 1}}, {"red", {1, 0, 0, 1}},       {"green", {0, 1, 0, 1}},
        {"blue", {0, 0, 1, 1}},          {"yellow", {1, 1, 0, 1}},    {"cyan", {0, 1, 1, 1}},
        {"magenta", {1, 0, 1, 1}},       {"orange", {1, 0.5f, 0, 1}}, {"transparent", {0, 0, 0, 0}}};
    return names;
}

[[noreturn]] void bad(const std::string& text) {
    std::vector<std::string> names;
    std::string list;
    for (const auto& [name, value] : color_names()) {
        names.push_back(name);
        list += (list.empty() ? "" : ", ") + name;
    }
    throw InputError("bad colour '" + text + "' (use #rrggbb, r,g,b with components in [0,1], or a name: " + list +
                     ")" + did_you_mean(text, names));
}

}  // namespace

glm::vec4 parse_color(const std::string& text) {
    const auto& names = color_names();
    const std::string lower = lower_ascii(text);
    if (auto it = names.find(lower); it != names.end()) return it->second;

    if (!lower.empty() && lower[0] == '#') {
        std::string hex = lower.substr(1);
        if (hex.size() == 3) hex = {hex[0], hex[0], hex[1], hex[1], hex[2], hex[2]};
        if (hex.size() != 6 && hex.size() != 8) bad(text);
        if (!std::all_of(hex.begin(), hex.end(), [](unsigned char c) { return std::isxdigit(c); })) bad(text);
        glm::vec4 c(0, 0, 0, 1);
        for (size_t i = 0; i < hex.size() / 2; ++i)
            c[int(i)] = float(std::stoi(hex.substr(2 * i, 2), nullptr, 16)) / 255.0f;
        return c;
    }

    std::vector<float> parts;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        float v = 0;
        const char* b = item.data();
        while (b < item.data() + item.size() && std::isspace((unsigned char)*b)) ++b;
        auto [ptr, ec] = std::from_chars(b, item.data() + item.size(), v);
        if (ec != std::errc() || ptr != item.data() + item.size() || !std::isfinite(v) || v < 0 || v > 1) bad(text);
        parts.push_back(v);
    }
    if (parts.size() == 1) return {parts[0], parts[0], parts[0], 1};  // grey level
    if (parts.size() == 3) return {parts[0], parts[1], parts[2], 1};
    if (parts.size() == 4) return {parts[0], parts[1], parts[2], parts[3]};
    bad(text);
}

float srgb_to_linear(float c) {
    return c < 0.04045f ? c * 0.0773993808f : std::pow(c * 0.9478672986f + 0.0521327014f, 2.4f);
}

glm::vec3 srgb_to_linear(const glm::vec3& c) { return {srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b)}; }

float linear_to_srgb(float c) { return c < 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 0.41666f) - 0.055f; }

glm::vec3 linear_to_srgb(const glm::vec3& c) { return {linear_to_srgb(c.r), linear_to_srgb(c.g), linear_to_srgb(c.b)}; }

}  // namespace inkshade
