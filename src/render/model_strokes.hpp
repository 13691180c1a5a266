// The strokes a shading model draws over its fill (ShadingModel::strokes): the line layer
// that the render adds to the style's lines.
#pragma once
#include <optional>

#include "inkshade/camera.hpp"
#include "inkshade/lines.hpp"
#include "inkshade/mesh.hpp"
#include "inkshade/shading.hpp"

namespace inkshade::render {

// The layer of type model.strokes with the values of the model's parameters that the type
// has too (given or default), and the type's `light` (a direction in camera space) pointing
// from the model's centre towards `light`; nothing when the model draws no strokes.
std::optional<LineSettings> model_strokes(const ShadingModel& model, const ParamValues& values, const Light& light,
                                          const Camera& camera, const BoundingBox& bounds);

}  // namespace inkshade::render
