// Colour values as users write them: "#rgb", "#rrggbb", "#rrggbbaa", "r,g,b[,a]" with
// components in [0,1], or a name (black, white, grey, red, green, blue, yellow, ...).
#pragma once
#include <string>

#include <glm/glm.hpp>

namespace inkshade {

// Throws InputError("bad colour 'x' (use #rrggbb, r,g,b in [0,1] or a name)").
glm::vec4 parse_color(const std::string& text);

}  // namespace inkshade
