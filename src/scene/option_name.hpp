// How a request's errors name an option: the command line's "--light-pos" or the Python
// keyword "light_pos", from the option's command-line name without dashes.
#pragma once
#include <string>

#include "inkshade/scene.hpp"

namespace inkshade {

inline std::string option_name(OptionNames names, const std::string& option) {
    if (names == OptionNames::Cli) return "--" + option;
    if (option == "lines") return "types";  // Renderer.lines(types) and svg(types)
    std::string keyword = option;
    for (char& c : keyword)
        if (c == '-') c = '_';
    return keyword;
}

}  // namespace inkshade
