// The style changes of the viewer's keys, as plain functions of the style: the window applies
// them, and a script is checked before the window opens by applying them to a copy
// (check_script), so a `set` after `key F` is checked against the model F switches to.
#pragma once
#include <cstddef>

#include "inkshade/style.hpp"

namespace inkshade::viewer {

// F: the next shading model but the debug views (which have their own panel), as
// `--shading NAME` gives it (its defaults, light and background) with the style's line types.
Style next_shading_model_style(const Style& style);

// 1-9: the index-th line type of line_types() on (with its defaults) or off; past the last
// one, nothing.
void toggle_line_type(Style& style, size_t index);

}  // namespace inkshade::viewer
