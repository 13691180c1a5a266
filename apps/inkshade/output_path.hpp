// Checks of an output path before any work, so a bad path fails fast with exit 2.
#pragma once
#include <string>

namespace inkshade::cli {

// Throws InputError when `path` (given by `option`) is empty, a directory, or in a directory
// that does not exist or is not writable.
void check_output_path(const std::string& option, const std::string& path);

}  // namespace inkshade::cli
