#include "render/color_convention.hpp"

namespace inkshade::render {

ColorConvention color_convention(const ShadingModel& model, const ParamValues& values, const RenderOptions& options) {
    if (model.debug_view) return ColorConvention::Display;
    // The three.js models, and mtoon with `convention = threejs` (three-vrm's linear workflow).
    if (options.srgb_output || model.reads(ShadingInputKind::LinearLight, values)) return ColorConvention::Linear;
    return ColorConvention::Display;
}

}  // namespace inkshade::render
