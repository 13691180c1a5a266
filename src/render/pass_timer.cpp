#include "render/pass_timer.hpp"

namespace inkshade::render {

PassTimer::PassTimer(std::vector<PassTiming>* out, std::string name) : out_(out), name_(std::move(name)) {
    if (!out_) return;
    glFinish();
    start_ = std::chrono::steady_clock::now();
    begin_ = gpu::GlQuery::create(GL_TIMESTAMP);
    end_ = gpu::GlQuery::create(GL_TIMESTAMP);
    glQueryCounter(begin_.id(), GL_TIMESTAMP);
}

PassTimer::~PassTimer() {
    if (!out_) return;
    glQueryCounter(end_.id(), GL_TIMESTAMP);
    glFinish();
    const auto end = std::chrono::steady_clock::now();
    GLuint64 t0 = 0, t1 = 0;
    glGetQueryObjectui64v(begin_.id(), GL_QUERY_RESULT, &t0);  // available: finished above
    glGetQueryObjectui64v(end_.id(), GL_QUERY_RESULT, &t1);
    out_->push_back({name_, std::chrono::duration<double, std::milli>(end - start_).count(),
                     t1 >= t0 ? double(t1 - t0) * 1e-6 : 0.0});
}

}  // namespace inkshade::render
