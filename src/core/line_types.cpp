// The registry behind [[lines]] in style files, --lines and `inkshade styles`.
#include <algorithm>
#include <stdexcept>

#include "core/name_suggestion.hpp"
#include "inkshade/error.hpp"
#include "inkshade/lines.hpp"

namespace inkshade {

namespace {

std::vector<LineType>& registry() {
    static std::vector<LineType> types;
    return types;
}

}  // namespace

const ParamSpec* LineType::param(const std::string& param_name) const { return find_param(params, param_name); }

std::vector<ParamSpec> stroke_params(glm::vec3 color, float width_px) {
    return {color_param("color", color, "stroke colour"),
            float_param("opacity", 1.0f, 0.0f, 1.0f, "stroke opacity (1 = opaque)"),
            float_param("width", width_px, 0.0f, 64.0f, "stroke width in pixels of the output image")};
}

LineTypeRegistration::LineTypeRegistration(LineType type) { registry().push_back(std::move(type)); }

std::vector<const LineType*> line_types() {
    std::vector<const LineType*> out;
    for (const auto& t : registry()) out.push_back(&t);
    std::sort(out.begin(), out.end(), [](auto* a, auto* b) { return a->name < b->name; });
    return out;
}

const LineType& line_type(const std::string& name) {
    for (const auto& t : registry())
        if (t.name == name) return t;
    for (const auto& t : registry())  // names are lower case; what users type may not be
        if (equal_ignoring_case(t.name, name)) return t;
    std::string names;
    std::vector<std::string> candidates;
    for (const auto* t : line_types()) {
        names += (names.empty() ? "" : ", ") + t->name;
        candidates.push_back(t->name);
    }
    throw InputError("unknown line type '" + name + "' (choose " + (names.empty() ? "none registered" : names) + ")" +
                     did_you_mean(name, candidates));
}

const ParamValue& line_param(const LineSettings& settings, const std::string& name) {
    const ParamSpec* spec = line_type(settings.type).param(name);
    if (!spec) throw std::logic_error("line type " + settings.type + " has no parameter " + name);
    return value_or_default(*spec, settings.params);
}

Stroke stroke_of(const LineSettings& settings) {
    const ParamValue& c = line_param(settings, "color");
    return {glm::vec3(c.at(0), c.at(1), c.at(2)), line_param(settings, "opacity").at(0),
            line_param(settings, "width").at(0)};
}

}  // namespace inkshade
