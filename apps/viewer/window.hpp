// The viewer's window: a GLFW window with an OpenGL 4.5 core context and Dear ImGui on it. It
// turns the window's mouse, key and drop events into WindowInput calls, leaving out those the
// panels take (a click on a panel, typing into a field).
#pragma once
#include <string>

#include <glm/glm.hpp>

struct GLFWwindow;

namespace inkshade::viewer {

// What the viewer does with the window's events (input.hpp).
class WindowInput {
public:
    virtual ~WindowInput() = default;
    // A mouse button pressed or released at (x, y) in screen coordinates (GLFW_MOUSE_BUTTON_*).
    virtual void mouse_button(int button, bool pressed, double x, double y) = 0;
    virtual void mouse_moved(double x, double y) = 0;
    virtual void scrolled(double steps) = 0;  // > 0: away from the user
    // A key pressed: upper-case letters and digits are their ASCII codes (GLFW's key codes).
    virtual void key(int key) = 0;
    virtual void dropped(const std::string& path) = 0;
};

class Window {
public:
    // Opens a `width` x `height` window (screen coordinates); `vsync` off for scripted runs.
    // Throws RuntimeError with one line suggesting `inkshade render` when there is no display
    // or no OpenGL 4.5.
    Window(int width, int height, bool vsync);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // Where the events go from now on (none: dropped). Esc closes the window itself.
    void set_input(WindowInput* input) { input_ = input; }

    void make_current();
    // Handles the events that arrived; `wait` sleeps until one does (at most a quarter second).
    void poll_events(bool wait);
    bool closed() const;
    glm::ivec2 framebuffer_size() const;  // pixels
    glm::ivec2 size() const;              // screen coordinates

    // One frame of the GUI: begin_gui, then Dear ImGui calls, then end_gui draws them over
    // what the window's framebuffer holds; swap shows it.
    void begin_gui();
    void end_gui();
    void swap();

private:
    void install_callbacks();
    static Window& of(GLFWwindow* w);

    GLFWwindow* window_ = nullptr;
    WindowInput* input_ = nullptr;
};

}  // namespace inkshade::viewer
