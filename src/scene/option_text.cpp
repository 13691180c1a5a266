// Option values as text, as the command line and manifests give them. Each error names the
// option and repeats the text, in one line.
#include <charconv>
#include <cmath>
#include <sstream>

#include "inkshade/color.hpp"
#include "inkshade/error.hpp"
#include "inkshade/options.hpp"
#include "inkshade/scene.hpp"
#include "io/text_scanner.hpp"

namespace inkshade {

glm::ivec2 parse_image_size(const std::string& option, const std::string& text) {
    int w = 0, h = 0;
    char x = 0;
    std::istringstream in(text);
    if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || !in.eof() || w <= 0 || h <= 0 || w > 16384 || h > 16384)
        throw InputError(option + ": expected WxH with each side in 1..16384, got " + io::quote_token(text));
    return {w, h};
}

glm::vec3 parse_vec3(const std::string& option, const std::string& text) {
    glm::vec3 v(0.0f);
    std::stringstream ss(text);
    std::string item;
    int i = 0;
    while (std::getline(ss, item, ',')) {
        float f = 0;
        auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), f);
        if (i >= 3 || item.empty() || ec != std::errc() || ptr != item.data() + item.size() || !std::isfinite(f))
            throw InputError(option + ": expected x,y,z but got " + io::quote_token(text));
        v[i++] = f;
    }
    if (i != 3) throw InputError(option + ": expected x,y,z but got " + io::quote_token(text));
    return v;
}

glm::vec4 parse_color(const std::string& option, const std::string& text) {
    try {
        return parse_color(text);
    } catch (const InputError& e) {
        throw InputError(option + ": " + e.what());
    }
}

SectionPlane parse_section_plane(const std::string& option, const std::string& text) {
    const std::string expected = option + ": expected X,Y,Z,NX,NY,NZ (a point and a normal not zero), got ";
    float v[6] = {};
    std::stringstream ss(text);
    std::string item;
    int i = 0;
    while (std::getline(ss, item, ',')) {
        auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), v[i < 6 ? i : 0]);
        if (i >= 6 || item.empty() || ec != std::errc() || ptr != item.data() + item.size() || !std::isfinite(v[i]))
            throw InputError(expected + io::quote_token(text));
        ++i;
    }
    const glm::vec3 normal(v[3], v[4], v[5]);
    const float length = glm::length(normal);
    if (i != 6 || !(length > 0.0f) || !std::isfinite(length)) throw InputError(expected + io::quote_token(text));
    return {.point = {v[0], v[1], v[2]}, .normal = normal / length};
}

LightType parse_light_type(const std::string& option, const std::string& text) {
    if (text == "directional") return LightType::Directional;
    if (text == "point") return LightType::Point;
    throw InputError(option + ": expected directional or point, got " + io::quote_token(text));
}

NamedWeight parse_named_weight(const std::string& option, const std::string& text) {
    const size_t eq = text.rfind('=');
    float w = 0;
    if (eq != std::string::npos && eq > 0) {
        const char* end = text.data() + text.size();
        auto [ptr, ec] = std::from_chars(text.data() + eq + 1, end, w);
        if (ec == std::errc() && ptr == end && eq + 1 < text.size() && std::isfinite(w)) return {text.substr(0, eq), w};
    }
    throw InputError(option + ": expected NAME=WEIGHT, got " + io::quote_token(text));
}

std::vector<NamedWeight> parse_named_weights(const std::string& option, const std::string& text) {
    std::vector<NamedWeight> out;
    for (const std::string& item : split_option_list(text)) out.push_back(parse_named_weight(option, item));
    return out;
}

}  // namespace inkshade
