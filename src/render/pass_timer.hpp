// Times one pass (benchmark mode only): wall time with the GPU work finished (glFinish) before
// and after it, and GPU time from timestamp queries around it (ARB_timer_query, core since 3.3).
#pragma once
#include <chrono>
#include <string>
#include <vector>

#include "gpu/gl_handle.hpp"
#include "inkshade/renderer.hpp"

namespace inkshade::render {

class PassTimer {
public:
    // Without `out` it does nothing.
    PassTimer(std::vector<PassTiming>* out, std::string name);
    ~PassTimer();
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;

private:
    std::vector<PassTiming>* out_;
    std::string name_;
    std::chrono::steady_clock::time_point start_;
    gpu::GlQuery begin_, end_;
};

}  // namespace inkshade::render
