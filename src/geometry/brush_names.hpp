// The brushes GPU strokes can draw with (the `brush` parameter of object-space line types,
// docs/lines.md): "none" is the solid stroke; each other name is an image of data/brushes/
// (render/brush_texture.hpp). The SVG keeps the stroke's outline and names the brush only.
#pragma once
#include <string>
#include <vector>

namespace inkshade::geometry {

// In the order of the parameter's choices: index 0 is "none".
inline const std::vector<std::string>& brush_names() {
    static const std::vector<std::string> names = {"none", "pencil", "ink", "chalk", "marker"};
    return names;
}

}  // namespace inkshade::geometry
