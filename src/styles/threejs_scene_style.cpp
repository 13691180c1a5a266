// A three.js scene description (inkshade/threejs_scene.hpp) as an Inkshade style: the parts a
// style holds (material, outline, light colours, background); camera, light placement and
// image size are the caller's (the CLI maps them to its options, docs/threejs.md).
#include <filesystem>

#include "inkshade/error.hpp"
#include "inkshade/style.hpp"
#include "inkshade/threejs_scene.hpp"

namespace inkshade {

namespace {

// Checks `values` against `params`, naming the JSON field of a bad one.
ParamValues checked(const std::vector<ParamSpec>& params, const ParamValues& values,
                    const std::map<std::string, std::string>& fields, const std::string& prefix,
                    const std::string& source) {
    ParamValues out;
    for (const auto& [name, value] : values) {
        const ParamSpec* spec = find_param(params, name);
        if (!spec) continue;  // e.g. the light intensities of an unlit material
        try {
            out[name] = check_param_value(*spec, value);
        } catch (const InputError& e) {
            auto f = fields.find(name);
            throw InputError(source, (f != fields.end() ? f->second : prefix + name) + ": " + e.what());
        }
    }
    return out;
}

}  // namespace

Style threejs_scene_style(const ThreejsScene& scene) {
    Style style;
    style.name = std::filesystem::path(scene.source).stem().string();
    style.description = "three.js scene " + scene.source;
    const ShadingModel& model = shading_model(scene.model);
    style.shading.model = model.name;
    style.shading.params = checked(model.params, scene.params, scene.param_fields, "material.", scene.source);
    style.light_color = scene.light_color;
    style.ambient = scene.ambient;
    if (scene.base_color) {
        // MToonMaterial's litFactor multiplies the mesh's colours and texture, as --base-color does.
        style.shading.base_color = *scene.base_color;
        style.shading.base_color_use = BaseColorUse::Multiply;
    }
    // A model without three.js's light parameters (mtoon) takes the lights' intensity, decay
    // and distance as the style's [light] values, and the ambient intensity in its colour.
    for (LightValue which : {LightValue::Intensity, LightValue::Decay, LightValue::Distance}) {
        const char* name = light_value_param(which);
        auto it = scene.params.find(name);
        if (it == scene.params.end() || model.param(name) || it->second.size() != 1) continue;
        try {
            set_light_value(style, which, it->second[0]);
        } catch (const InputError& e) {
            auto f = scene.param_fields.find(name);
            throw InputError(scene.source, (f != scene.param_fields.end() ? f->second : name) + ": " + e.what());
        }
    }
    if (auto it = scene.params.find("ambient-intensity");
        it != scene.params.end() && !model.param("ambient-intensity") && it->second.size() == 1)
        style.ambient = scene.ambient * it->second[0];
    style.background = scene.background;
    if (scene.outline)
        style.lines.push_back({"threejs-outline", checked(line_type("threejs-outline").params, *scene.outline, {},
                                                          "outline.", scene.source)});
    return style;
}

}  // namespace inkshade
