// What `inkshade batch` prints while it runs: on a terminal one line that updates in place
// (count, images/s, ETA); otherwise one line per job, for logs. Failures are always printed.
#pragma once
#include <string>

#include "inkshade/batch.hpp"

namespace inkshade::cli {

class BatchProgressPrinter {
public:
    // `tty`: stderr is a terminal; `quiet`: failures only.
    BatchProgressPrinter(bool tty, bool quiet) : tty_(tty), quiet_(quiet) {}

    void operator()(const BatchEvent& event);
    // Clears the updating line (before the summary is printed).
    void finish();

private:
    bool tty_, quiet_;
    bool line_shown_ = false;
    double last_draw_ = -1.0;
    size_t failed_ = 0;
};

// "24 jobs: 20 done, 4 skipped, 0 failed in 5.2 s (3.8 images/s)".
std::string summary_line(const BatchSummary& summary);

}  // namespace inkshade::cli
