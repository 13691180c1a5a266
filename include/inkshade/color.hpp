// Colour values as users write them: "#rgb", "#rrggbb", "#rrggbbaa", "r,g,b[,a]" with
// components in [0,1], or a name (black, white, grey, red, green, blue, yellow, ...).
#pragma once
#include <string>

#include <glm/glm.hpp>

namespace inkshade {

// Throws InputError("bad colour 'x' (use #rrggbb, r,g,b with components in [0,1], or a name: black,
// ...)"), with " (did you mean 'red'?)" when the text is close to a name. Names ignore case.
glm::vec4 parse_color(const std::string& text);

// The sRGB transfer function (IEC 61966-2-1) with three.js's ColorManagement constants:
// sRGB-encoded components (as in "#ff8800") to linear light and back.
float srgb_to_linear(float c);
glm::vec3 srgb_to_linear(const glm::vec3& c);
float linear_to_srgb(float c);
glm::vec3 linear_to_srgb(const glm::vec3& c);

}  // namespace inkshade
