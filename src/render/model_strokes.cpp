#include "render/model_strokes.hpp"

#include <cmath>

namespace inkshade::render {

std::optional<LineSettings> model_strokes(const ShadingModel& model, const ParamValues& values, const Light& light,
                                          const Camera& camera, const BoundingBox& bounds) {
    if (model.strokes.empty()) return std::nullopt;
    const LineType& type = line_type(model.strokes);
    LineSettings layer{.type = type.name, .params = {}};
    for (const ParamSpec& spec : model.params)
        if (const ParamSpec* same = type.param(spec.name); same && same->type == spec.type)
            layer.params[spec.name] = value_or_default(spec, values);
    if (type.param("light")) {
        // A directional light shines from its position towards its target; a point or spot
        // light is taken from the model's centre.
        const glm::vec3 from = light.type == LightType::Directional ? light.target : bounds.center();
        glm::vec3 d = light.position - from;
        const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
        const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
        const glm::vec3 up = glm::cross(right, forward);
        const float len = glm::length(d);
        d = len > 0.0f && std::isfinite(len) ? d / len : -forward;
        layer.params["light"] = {glm::dot(d, right), glm::dot(d, up), -glm::dot(d, forward)};
    }
    return layer;
}

}  // namespace inkshade::render
