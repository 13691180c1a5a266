// What fuzz_scene does with one input (replayed by tests/styles/fuzz_regressions_test.cpp): the
// three.js scene JSON of `render --scene` (docs/threejs.md) through parse_threejs_scene, and a
// scene that parses through threejs_scene_style (its values against the models' ranges). Errors
// must be one line starting with the source; a style that comes out must survive the
// format_style -> parse_style round trip, as --save-style needs.
#pragma once
#include <string>
#include <string_view>

#include "fuzz_common.hpp"
#include "inkshade/style.hpp"
#include "inkshade/threejs_scene.hpp"
#include "style_target.hpp"

namespace inkshade::fuzz {

inline void scene_input(std::string_view data) {
    const std::string source = "scene.json";
    Style style;
    try {
        style = threejs_scene_style(parse_threejs_scene(data, source));
    } catch (const InputError& e) {
        check_error(e, source);
        return;
    }
    check_style_round_trip(style, "scene.toml");  // the saved file's name gives the same style name
}

}  // namespace inkshade::fuzz
