#include "viewer.hpp"

#include <imgui.h>

#include <iostream>

#include "input.hpp"
#include "panels.hpp"
#include "script_runner.hpp"
#include "viewer_script.hpp"
#include "viewer_session.hpp"
#include "window.hpp"

namespace inkshade::viewer {

namespace {

void save_screenshot(ViewerSession& session, const std::string& path, glm::ivec2 size) {
    try {
        write_png(path, session.canvas().read_window(size.x, size.y));
        std::cerr << "inkshade view: screenshot " << path << "\n";
    } catch (const std::exception& e) {
        session.report(e.what(), true);
    }
}

// One frame: the rendered image 1:1 under the panels.
void draw_frame(Window& window, ViewerSession& session) {
    const glm::ivec2 size = window.framebuffer_size();
    session.render(size);
    window.begin_gui();
    ImGui::GetBackgroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(session.canvas().texture_id()), ImVec2(0, 0),
                                             ImGui::GetIO().DisplaySize);
    if (session.gui) draw_panels(session);
    session.canvas().clear_window(size.x, size.y, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
    window.end_gui();
}

// Until the window is closed, the script ends or quits, or `frames` are shown. Interactive:
// sleeps until input arrives; scripted: polls, one command a frame.
int run_frames(Window& window, ViewerSession& session, ScriptRunner& script, const ViewerOptions& options) {
    for (int frame = 1; !window.closed() && !script.quit(); ++frame) {
        window.poll_events(/*wait=*/!script.scripted() && options.frames == 0);
        if (script.scripted() && options.frames == 0 && script.ended()) break;
        std::string screenshot = script.step(session);
        draw_frame(window, session);
        const bool last = options.frames > 0 && frame >= options.frames;
        if (last && !options.screenshot.empty()) screenshot = options.screenshot;
        if (!screenshot.empty()) save_screenshot(session, screenshot, window.framebuffer_size());
        window.swap();
        if (last) break;
    }
    return 0;
}

}  // namespace

int run_viewer(const ViewerOptions& options) {
    std::vector<ScriptCommand> commands;
    if (!options.script.empty()) {  // a bad script fails before the window opens
        commands = read_script(options.script);
        check_script(commands, options.scene, options.script);
    }
    ScriptRunner script(std::move(commands));
    Window window(options.scene.options.width, options.scene.options.height,
                  /*vsync=*/!script.scripted() && options.frames == 0);
    ViewerSession session(options.scene, window, options.gui);
    ViewerInput input(session, window);
    window.set_input(&input);
    return run_frames(window, session, script, options);
}

}  // namespace inkshade::viewer
