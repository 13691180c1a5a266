// The registry behind [[lines]] in style files, --lines and `inkshade styles`.
#include <stdexcept>

#include "core/registry.hpp"
#include "inkshade/lines.hpp"

namespace inkshade {

namespace {

Registry<LineType>& registry() {
    static Registry<LineType> types("line type");
    return types;
}

}  // namespace

const ParamSpec* LineType::param(const std::string& param_name) const { return find_param(params, param_name); }

std::vector<ParamSpec> stroke_params(glm::vec3 color, float width_px) {
    return {color_param("color", color, "stroke colour"),
            float_param("opacity", 1.0f, 0.0f, 1.0f, "stroke opacity (1 = opaque)"),
            float_param("width", width_px, 0.0f, 64.0f, "stroke width in pixels of the output image")};
}

LineTypeRegistration::LineTypeRegistration(LineType type) { registry().add(std::move(type)); }

std::vector<const LineType*> line_types() { return registry().list(); }

const LineType& line_type(const std::string& name) { return registry().at(name); }

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
