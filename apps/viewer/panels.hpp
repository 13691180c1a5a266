// The viewer's Dear ImGui panels (docs/viewer.md, "Panels"): timings, model, style, lines,
// light and camera, save. Each edits the session and marks it changed.
#pragma once
#include "viewer_session.hpp"

namespace inkshade::viewer {

// Draws the panels' window for this frame (between Window::begin_gui and end_gui).
void draw_panels(ViewerSession& session);

}  // namespace inkshade::viewer
