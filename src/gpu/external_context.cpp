// A context created and owned by a window toolkit: the renderer only makes it current.
#include "gpu/gl_context.hpp"

namespace inkshade::gpu {

namespace {

class ExternalContext final : public GlContext {
public:
    explicit ExternalContext(std::function<void()> make_current) : make_current_(std::move(make_current)) {}
    void make_current() override {
        if (make_current_) make_current_();
    }

private:
    std::function<void()> make_current_;
};

}  // namespace

std::unique_ptr<GlContext> wrap_external_context(std::function<void()> make_current) {
    auto context = std::make_unique<ExternalContext>(std::move(make_current));
    context->make_current();
    pin_driver_modules_for_leak_reports();  // the window's driver is loaded by now
    return context;
}

}  // namespace inkshade::gpu
