// Runs a checked script (viewer_script.hpp) one command a frame on the viewer's session.
#pragma once
#include <string>
#include <vector>

#include "viewer_script.hpp"
#include "viewer_session.hpp"

namespace inkshade::viewer {

class ScriptRunner {
public:
    explicit ScriptRunner(std::vector<ScriptCommand> commands) : commands_(std::move(commands)) {}

    // Whether there is a script at all (then the window polls rather than waits for input).
    bool scripted() const { return !commands_.empty(); }
    // Runs this frame's command, if any: after `frames N`, none for N frames. Returns the path
    // of a `screenshot` to save once the frame is drawn, else "".
    std::string step(ViewerSession& session);
    // Every command has run and the frames the last asked for are shown.
    bool ended() const { return wait_frames_ == 0 && next_ >= commands_.size(); }
    bool quit() const { return quit_; }  // `quit` ran

private:
    void run(const ScriptCommand& command, ViewerSession& session);

    std::vector<ScriptCommand> commands_;
    size_t next_ = 0;
    int wait_frames_ = 0;
    bool quit_ = false;
};

}  // namespace inkshade::viewer
