#include "script_runner.hpp"

namespace inkshade::viewer {

std::string ScriptRunner::step(ViewerSession& session) {
    if (wait_frames_ > 0) {
        --wait_frames_;
        return "";
    }
    if (next_ >= commands_.size()) return "";
    const ScriptCommand& c = commands_[next_++];
    if (c.kind == ScriptCommand::Screenshot) return c.argument;  // after the frame is drawn
    run(c, session);
    return "";
}

void ScriptRunner::run(const ScriptCommand& c, ViewerSession& session) {
    switch (c.kind) {
        case ScriptCommand::Frames: wait_frames_ = c.count; break;
        case ScriptCommand::Key: session.handle_key(c.count); break;
        case ScriptCommand::Set: session.apply_set(c.argument); break;
        case ScriptCommand::StyleName: session.load_style_named(c.argument); break;
        case ScriptCommand::LightPos: session.move_light(c.vector); break;
        case ScriptCommand::Orbit: session.orbit_camera(c.vector.x, c.vector.y); break;
        case ScriptCommand::Zoom: session.zoom_camera(c.vector.x); break;
        case ScriptCommand::Open: session.open_model(c.argument); break;
        case ScriptCommand::Screenshot: break;  // step returns it
        case ScriptCommand::SaveFrame: session.save_frame(c.argument); break;
        case ScriptCommand::SaveStyle: session.save_style_file(c.argument); break;
        case ScriptCommand::Gui: session.gui = c.count != 0; break;
        case ScriptCommand::Quit: quit_ = true; break;
    }
}

}  // namespace inkshade::viewer
