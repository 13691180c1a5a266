// What the --timing modes of `render` and `lines` print: medians and the peak memory.
#pragma once
#include <vector>

namespace inkshade::cli {

double median(std::vector<double> values);  // 0 for none
double peak_rss_mib();                      // the process's peak resident set so far

}  // namespace inkshade::cli
