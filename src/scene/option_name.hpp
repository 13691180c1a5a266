// How a request's errors name an option: the command line's "--light-pos" or the Python
// keyword "light_pos", from the option's command-line name without dashes.
#pragma once
#include <string>

#include "inkshade/scene.hpp"

namespace inkshade {

inline std::string option_name(OptionNames names, const std::string& option) {
    // The line drawing's types are `lines --lines` on the command line, Renderer.lines(types)
    // and svg(types) in Python.
    if (option == "vector-lines") return names == OptionNames::Cli ? "--lines" : "types";
    if (names == OptionNames::Cli) return "--" + option;
    if (names == OptionNames::Columns) return option;
    std::string keyword = option;
    for (char& c : keyword)
        if (c == '-') c = '_';
    return keyword;
}

}  // namespace inkshade
