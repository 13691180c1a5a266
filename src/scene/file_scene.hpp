// How a model file's light meets a shading model (file_scene.cpp; docs/inputs.md, "Cameras
// and lights").
#pragma once
#include "inkshade/scene.hpp"

namespace inkshade {

// The units a shading model takes its light in.
enum class LightUnits {
    // Colours on the display's scale (lambert, cel, toon, ...; mtoon's default convention): a
    // file light gives its direction, position and tint; the style's light colour its strength.
    Display,
    // The threejs-* models: light colour x the light-intensity parameter, with their own
    // distance falloff (light-decay, light-distance) and the spot cone.
    ThreejsParams,
    // Physical units in the renderer's light (mtoon's threejs convention): colour x intensity,
    // with three.js's distance falloff (decay, range window) and spot cone for point and spot
    // lights, the key light's as a file's.
    Physical,
};

LightUnits light_units(const ShadingSelection& shading);

// The renderer's light for the file's light under the style's shading model: placed by its
// node (a directional light 1.5 diagonals from the centre of `box`, against its direction).
Light file_scene_light(const FileLight& light, const Style& style, const BoundingBox& box);

}  // namespace inkshade
