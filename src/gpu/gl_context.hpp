// An OpenGL 4.5 core context: headless through EGL, or a window's (GLFW) made current by its owner.
#pragma once
#include <functional>
#include <memory>
#include <string>

namespace inkshade::gpu {

class GlContext {
public:
    virtual ~GlContext() = default;
    virtual void make_current() = 0;
    // GL_RENDERER / GL_VERSION of the current context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    std::string renderer() const;
    std::string version() const;
};

// Headless OpenGL 4.5 core through EGL: the surfaceless Mesa platform first (no X server, no
// GPU needed), then the EGL device platform (vendor drivers, e.g. NVIDIA). Throws
// RuntimeError with one line saying what is missing and which package provides it.
std::unique_ptr<GlContext> create_headless_context();

// Sanitizer builds: keeps the loaded GL driver modules mapped until exit, so leak reports of
// their teardown name them (tests/lsan.supp). Does nothing in other builds.
void pin_driver_modules_for_leak_reports();

// A context owned by someone else (a window), made current by `make_current`.
std::unique_ptr<GlContext> wrap_external_context(std::function<void()> make_current);

}  // namespace inkshade::gpu
