#include "window.hpp"

#define GLFW_INCLUDE_NONE  // the GL declarations are render's (inkshade/window_canvas.hpp)
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>

#include "inkshade/error.hpp"

namespace inkshade::viewer {

namespace {

std::string g_glfw_error;  // the last GLFW error, for the one-line message when a window fails

void glfw_error(int, const char* description) { g_glfw_error = description ? description : "unknown error"; }

bool gui_wants_mouse() { return ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse; }
bool gui_wants_keyboard() { return ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard; }

GLFWwindow* open_window(int width, int height) {
    glfwSetErrorCallback(glfw_error);
    if (!glfwInit())
        throw RuntimeError("cannot open a window (" + g_glfw_error +
                           "): no display; use `inkshade render` for images without a window, or run under xvfb-run");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);  // HiDPI: the window keeps its apparent size
    GLFWwindow* window = glfwCreateWindow(width, height, "inkshade", nullptr, nullptr);
    if (!window) {
        glfwTerminate();
        throw RuntimeError("cannot open an OpenGL 4.5 window (" + g_glfw_error + "); use `inkshade render` instead");
    }
    return window;
}

void start_gui(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini next to the user's files
    float sx = 1.0f, sy = 1.0f;
    glfwGetWindowContentScale(window, &sx, &sy);
    io.FontGlobalScale = std::max(1.0f, sx);
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450 core");
}

}  // namespace

Window::Window(int width, int height, bool vsync) : window_(open_window(width, height)) {
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(vsync ? 1 : 0);
    glfwSetWindowUserPointer(window_, this);
    // Input callbacks first: ImGui's GLFW backend chains to them when it installs its own.
    install_callbacks();
    start_gui(window_);
}

Window::~Window() {
    glfwMakeContextCurrent(window_);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
}

Window& Window::of(GLFWwindow* w) { return *static_cast<Window*>(glfwGetWindowUserPointer(w)); }

void Window::install_callbacks() {
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
        WindowInput* input = of(w).input_;
        if (!input || (gui_wants_mouse() && action == GLFW_PRESS)) return;
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(w, &x, &y);
        input->mouse_button(button, action == GLFW_PRESS, x, y);
    });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
        if (WindowInput* input = of(w).input_) input->mouse_moved(x, y);
    });
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double yoff) {
        WindowInput* input = of(w).input_;
        if (input && !gui_wants_mouse()) input->scrolled(yoff);
    });
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
        if (action != GLFW_PRESS || gui_wants_keyboard()) return;
        if (key == GLFW_KEY_ESCAPE)
            glfwSetWindowShouldClose(w, GLFW_TRUE);
        else if (WindowInput* input = of(w).input_)
            input->key(key);
    });
    glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
        WindowInput* input = of(w).input_;
        if (input && count > 0) input->dropped(paths[0]);
    });
}

void Window::make_current() { glfwMakeContextCurrent(window_); }

void Window::poll_events(bool wait) {
    if (wait)
        glfwWaitEventsTimeout(0.25);
    else
        glfwPollEvents();
}

bool Window::closed() const { return glfwWindowShouldClose(window_); }

glm::ivec2 Window::framebuffer_size() const {
    glm::ivec2 size(0);
    glfwGetFramebufferSize(window_, &size.x, &size.y);
    return size;
}

glm::ivec2 Window::size() const {
    glm::ivec2 size(1);
    glfwGetWindowSize(window_, &size.x, &size.y);
    return size;
}

void Window::begin_gui() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void Window::end_gui() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Window::swap() { glfwSwapBuffers(window_); }

}  // namespace inkshade::viewer
