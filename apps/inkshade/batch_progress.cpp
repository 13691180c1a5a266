#include "batch_progress.hpp"

#include <cmath>
#include <cstdio>

namespace inkshade::cli {

namespace {

std::string one_line(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

std::string duration(double seconds) {
    char buf[48];
    const long s = std::lround(seconds);
    if (s >= 3600)
        std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, (s / 60) % 60);
    else if (s >= 60)
        std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
    else
        std::snprintf(buf, sizeof buf, "%lds", s);
    return buf;
}

}  // namespace

void BatchProgressPrinter::operator()(const BatchEvent& e) {
    if (e.status == BatchStatus::Failed) {
        failed_ += e.jobs;
        if (tty_ && line_shown_) std::fputs("\r\033[K", stderr);
        if (e.model_failed)
            std::fprintf(stderr, "inkshade: %s (%zu job%s failed)\n", one_line(e.reason).c_str(), e.jobs,
                         e.jobs == 1 ? "" : "s");
        else
            std::fprintf(stderr, "inkshade: %s: %s\n", e.job->stem.c_str(), one_line(e.reason).c_str());
        line_shown_ = false;
        last_draw_ = -1.0;
    } else if (!quiet_ && !tty_) {
        std::fprintf(stderr, "[%zu/%zu] %s %s\n", e.finished, e.total, e.status == BatchStatus::Done ? "done" : "skip",
                     e.job->stem.c_str());
    }
    if (quiet_ || !tty_) return;
    // A terminal: redraw at most 10 times a second, and for the last job.
    if (e.finished < e.total && last_draw_ >= 0.0 && e.seconds - last_draw_ < 0.1) return;
    last_draw_ = e.seconds;
    const double rate = e.seconds > 0.0 ? double(e.rendered) / e.seconds : 0.0;
    const size_t settled = e.rendered + failed_;
    const size_t left = e.to_render > settled ? e.to_render - settled : 0;
    std::string eta = rate > 0.0 ? "ETA " + duration(double(left) / rate) : "ETA --";
    std::fprintf(stderr, "\r\033[K[%zu/%zu] %.1f images/s, %s  %s", e.finished, e.total, rate, eta.c_str(),
                 e.job->stem.c_str());
    std::fflush(stderr);
    line_shown_ = true;
}

void BatchProgressPrinter::finish() {
    if (tty_ && line_shown_) std::fputs("\r\033[K", stderr);
    line_shown_ = false;
}

std::string summary_line(const BatchSummary& s) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%zu jobs: %zu done, %zu skipped, %zu failed in %.1f s (%.2f images/s)", s.total,
                  s.done, s.skipped, s.failed, s.seconds, s.seconds > 0.0 ? double(s.done) / s.seconds : 0.0);
    return buf;
}

}  // namespace inkshade::cli
