// The viewer's mouse and keys (docs/viewer.md, "Mouse and keys"): left drag orbits about the
// target, right or middle drag pans, the wheel zooms, a dropped file is opened, and the keys
// go to ViewerSession::handle_key.
#pragma once
#include "viewer_session.hpp"
#include "window.hpp"

namespace inkshade::viewer {

class ViewerInput final : public WindowInput {
public:
    ViewerInput(ViewerSession& session, const Window& window) : session_(session), window_(window) {}

    void mouse_button(int button, bool pressed, double x, double y) override;
    void mouse_moved(double x, double y) override;
    void scrolled(double steps) override;
    void key(int key) override { session_.handle_key(key); }
    void dropped(const std::string& path) override { session_.open_model(path); }

private:
    ViewerSession& session_;
    const Window& window_;
    bool dragging_ = false;
    int drag_button_ = -1;
    double last_x_ = 0.0, last_y_ = 0.0;
};

}  // namespace inkshade::viewer
