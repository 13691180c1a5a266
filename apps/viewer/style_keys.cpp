#include "style_keys.hpp"

#include <algorithm>
#include <vector>

#include "inkshade/lines.hpp"
#include "inkshade/shading.hpp"

namespace inkshade::viewer {

Style next_shading_model_style(const Style& style) {
    std::vector<const ShadingModel*> models;
    for (const ShadingModel* m : shading_models())
        if (!m->debug_view) models.push_back(m);
    size_t i = 0;
    while (i < models.size() && models[i]->name != style.shading.model) ++i;
    const ShadingModel* next = models[(i + 1) % models.size()];
    // So F shows each model as `inkshade render --shading NAME` would.
    Style out = shading_model_style(next->name);
    out.lines = style.lines;
    return out;
}

void toggle_line_type(Style& style, size_t index) {
    const std::vector<const LineType*> types = line_types();
    if (index >= types.size()) return;
    // The style's own [[lines]]; its line sets' lines (after them) stay as the file has them.
    auto it = std::find_if(style.lines.begin(), style.lines.end(),
                           [&](const LineSettings& l) { return l.type == types[index]->name && l.lineset.empty(); });
    if (it != style.lines.end()) {
        style.lines.erase(it);
        return;
    }
    const auto sets =
        std::find_if(style.lines.begin(), style.lines.end(), [](const LineSettings& l) { return !l.lineset.empty(); });
    style.lines.insert(sets, LineSettings{types[index]->name, {}});
}

}  // namespace inkshade::viewer
