// The inputs a shading model declares (inkshade/shading.hpp, ShadingInput) and whether its
// parameter values switch them on.
#include "inkshade/shading.hpp"

namespace inkshade {

ShadingInput vertex_attribute_input(std::string provider) {
    return {.kind = ShadingInputKind::VertexAttribute, .name = std::move(provider)};
}

ShadingInput shadow_map_input(std::string when) {
    return {.kind = ShadingInputKind::ShadowMap, .name = "shadow-map", .when = std::move(when)};
}

ShadingInput linear_light_input(std::string when, std::string when_choice) {
    return {.kind = ShadingInputKind::LinearLight,
            .name = "linear-light",
            .when = std::move(when),
            .when_choice = std::move(when_choice)};
}

bool ShadingModel::input_on(const ShadingInput& input, const ParamValues& values) const {
    if (input.when.empty()) return true;
    const ParamSpec* spec = param(input.when);
    if (!spec) return false;
    const float value = value_or_default(*spec, values).at(0);
    if (spec->type != ParamType::Choice || input.when_choice.empty()) return value != 0.0f;
    const size_t choice = size_t(value);
    return choice < spec->choices.size() && spec->choices[choice] == input.when_choice;
}

bool ShadingModel::reads(ShadingInputKind kind, const ParamValues& values) const {
    for (const ShadingInput& input : inputs)
        if (input.kind == kind && input_on(input, values)) return true;
    return false;
}

}  // namespace inkshade
