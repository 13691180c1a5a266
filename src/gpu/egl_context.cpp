// Headless EGL context. eglGetDisplay(EGL_DEFAULT_DISPLAY) fails (Mesa on Debian 12) without an X
// server, so use EGL_MESA_platform_surfaceless, falling back to EGL_EXT_platform_device.
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <dlfcn.h>
#include <link.h>

#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <vector>

#include "gpu/gl_context.hpp"
#include "inkshade/error.hpp"

namespace inkshade::gpu {

std::string GlContext::renderer() const {
    const GLubyte* s = glGetString(GL_RENDERER);
    return s ? reinterpret_cast<const char*>(s) : "unknown";
}
std::string GlContext::version() const {
    const GLubyte* s = glGetString(GL_VERSION);
    return s ? reinterpret_cast<const char*>(s) : "unknown";
}

namespace {

constexpr const char* kInstallHint =
    "install Mesa's EGL and software rasteriser: apt-get install libegl1 libegl-mesa0 "
    "libgl1-mesa-dri";

// One EGLDisplay per platform/device is shared by every context of the process, and
// eglTerminate is not reference-counted (EGL 1.5 section 3.2): count the renderers using each
// display so one renderer going away does not pull the display from under another.
std::mutex display_mutex;
std::map<EGLDisplay, int> display_users;

bool acquire_display(EGLDisplay display) {
    std::lock_guard lock(display_mutex);
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) return false;
    ++display_users[display];
    return true;
}

void release_display(EGLDisplay display) {
    std::lock_guard lock(display_mutex);
    if (--display_users[display] > 0) return;
    display_users.erase(display);
    eglTerminate(display);
}

class EglContext final : public GlContext {
public:
    EglContext(EGLDisplay display, EGLContext context) : display_(display), context_(context) {}
    ~EglContext() override {
        if (eglGetCurrentContext() == context_)
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        release_display(display_);
    }
    void make_current() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw RuntimeError("cannot make the EGL context current");
    }

private:
    EGLDisplay display_;
    EGLContext context_;
};

bool has_client_extension(const char* name) {
    const char* exts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!exts) return false;
    std::string all = std::string(" ") + exts + " ";
    return all.find(std::string(" ") + name + " ") != std::string::npos;
}

// Creates a GL 4.5 core context on display, or returns EGL_NO_CONTEXT.
EGLContext create_core_context(EGLDisplay display) {
    if (!acquire_display(display)) return EGL_NO_CONTEXT;
    if (!eglBindAPI(EGL_OPENGL_API)) {
        release_display(display);
        return EGL_NO_CONTEXT;
    }
    const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    // Surfaceless rendering needs no config on Mesa, but asking for one keeps drivers happy.
    if (!eglChooseConfig(display, config_attribs, &config, 1, &count) || count == 0) config = EGL_NO_CONFIG_KHR;
    const EGLint context_attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
    if (context == EGL_NO_CONTEXT) {
        release_display(display);
        return EGL_NO_CONTEXT;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        release_display(display);
        return EGL_NO_CONTEXT;
    }
    return context;
}

}  // namespace

// Sanitizer builds only: eglTerminate (or a window toolkit's teardown) unloads Mesa's driver,
// after which LeakSanitizer cannot name the module of the driver's known teardown leak and
// tests/lsan.supp cannot match it. Marking the loaded driver modules RTLD_NODELETE keeps them
// mapped until exit.
void pin_driver_modules_for_leak_reports() {
#ifdef INKSHADE_SANITIZE
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void*) {
        const char* name = info->dlpi_name;
        if (name &&
            (std::strstr(name, "_dri.so") || std::strstr(name, "libEGL_mesa") || std::strstr(name, "libGLX_mesa") ||
             std::strstr(name, "libgallium") || std::strstr(name, "libglapi")))
            dlopen(name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
        },
        nullptr);
#endif
}

std::unique_ptr<GlContext> create_headless_context() {
    // Without a GPU, Mesa picks its software rasteriser from GALLIUM_DRIVER: make it llvmpipe
    // (deterministic and fast), never softpipe, unless the user chose otherwise. Hardware
    // drivers ignore this variable.
    setenv("GALLIUM_DRIVER", "llvmpipe", /*overwrite=*/0);
    // Load the EGL library through epoxy; its absence shows as no client extensions.
    if (!epoxy_has_egl() || !has_client_extension("EGL_EXT_platform_base"))
        throw RuntimeError(std::string("no EGL library with EGL_EXT_platform_base found; ") + kInstallHint);

    std::vector<EGLDisplay> candidates;
    if (has_client_extension("EGL_MESA_platform_surfaceless"))
        candidates.push_back(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
    if (has_client_extension("EGL_EXT_platform_device") && has_client_extension("EGL_EXT_device_enumeration")) {
        EGLDeviceEXT devices[8];
        EGLint n = 0;
        if (eglQueryDevicesEXT(8, devices, &n))
            for (EGLint i = 0; i < n; ++i)
                candidates.push_back(eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr));
    }
    for (EGLDisplay display : candidates) {
        if (display == EGL_NO_DISPLAY) continue;
        EGLContext context = create_core_context(display);
        if (context == EGL_NO_CONTEXT) continue;
        auto ctx = std::make_unique<EglContext>(display, context);
        if (epoxy_gl_version() < 45) continue;  // destructor releases it
        pin_driver_modules_for_leak_reports();
        return ctx;
    }
    throw RuntimeError(std::string("no OpenGL 4.5 core context available through EGL "
                                   "(surfaceless or device platform); ") +
                       kInstallHint);
}

}  // namespace inkshade::gpu
