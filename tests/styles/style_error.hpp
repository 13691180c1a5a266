// The message parse_style gives for a style text ("" when it parses): for the tests of bad
// style files.
#pragma once
#include <string>

#include "inkshade/error.hpp"
#include "inkshade/style.hpp"

namespace inkshade::test {

inline std::string style_error(const std::string& text) {
    try {
        parse_style(text, "my.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace inkshade::test
