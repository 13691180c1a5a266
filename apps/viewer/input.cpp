#include "input.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>

namespace inkshade::viewer {

void ViewerInput::mouse_button(int button, bool pressed, double x, double y) {
    dragging_ = pressed;
    drag_button_ = button;
    last_x_ = x, last_y_ = y;
}

void ViewerInput::mouse_moved(double x, double y) {
    if (!dragging_) return;
    const double dx = x - last_x_, dy = y - last_y_;
    last_x_ = x, last_y_ = y;
    if (drag_button_ == GLFW_MOUSE_BUTTON_LEFT)
        session_.orbit_camera(float(-0.4 * dx), float(0.4 * dy));
    else
        session_.pan_camera(float(dx), float(dy), window_.size().y);
}

void ViewerInput::scrolled(double steps) { session_.zoom_camera(float(std::pow(0.9, steps))); }

}  // namespace inkshade::viewer
