// LineExtractor's timings (LineTiming): milliseconds summed per stage over the layers of a
// draw, stages in the order they are first reported (what `--timing` prints and batch metadata
// `timings_ms` records).
#pragma once
#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "inkshade/line_drawing.hpp"

namespace inkshade::geometry {

// Adds `ms` to `stage` of `out`, appending the stage when it is new; nothing when `out` is null.
inline void add_timing(std::vector<LineTiming>* out, const std::string& stage, double ms) {
    if (!out) return;
    for (LineTiming& t : *out)
        if (t.stage == stage) {
            t.milliseconds += ms;
            return;
        }
    out->push_back({stage, ms});
}

// Times one stage from construction to destruction, then adds it to `out` (add_timing): a stage
// that began inside this one reports itself first.
class StageTimer {
public:
    StageTimer(std::vector<LineTiming>* out, std::string stage) : out_(out), stage_(std::move(stage)) {}
    ~StageTimer() {
        const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start_;
        add_timing(out_, stage_, elapsed.count() - excluded_ms_);
    }
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;

    // Time spent inside this stage that another stage reports (lazy mesh-wide work).
    void exclude(double ms) { excluded_ms_ += ms; }

private:
    std::vector<LineTiming>* out_;
    std::string stage_;
    double excluded_ms_ = 0.0;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace inkshade::geometry
