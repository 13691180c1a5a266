// Dear ImGui widgets for typed parameters (inkshade/params.hpp): one widget per ParamSpec, so
// every shading model and line type gets its panel without code of its own.
#pragma once
#include <vector>

#include "inkshade/params.hpp"

namespace inkshade::viewer {

// Draws a widget per parameter; edits go into `values`. Returns true when a value changed.
bool param_widgets(const std::vector<ParamSpec>& params, ParamValues& values);

}  // namespace inkshade::viewer
