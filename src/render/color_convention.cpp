#include "render/color_convention.hpp"

namespace inkshade::render {

ColorConvention color_convention(const ShadingModel& model, const ParamValues& values, const RenderOptions& options) {
    if (model.debug_view) return ColorConvention::Display;
    if (options.srgb_output || model.linear_light) return ColorConvention::Linear;
    // mtoon's `convention = threejs`: three-vrm's linear workflow on three.js.
    if (const ParamSpec* spec = model.param("convention"); spec && spec->type == ParamType::Choice) {
        const size_t choice = size_t(value_or_default(*spec, values).at(0));
        if (choice < spec->choices.size() && spec->choices[choice] == "threejs") return ColorConvention::Linear;
    }
    return ColorConvention::Display;
}

}  // namespace inkshade::render
