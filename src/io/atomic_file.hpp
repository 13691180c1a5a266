// Atomic output: write to a temporary file beside the target, then rename over it, so a
// failed or interrupted run never leaves a partial file: every output is written atomically.
#pragma once
#include <string>
#include <string_view>

namespace inkshade::io {

// Writes bytes to path atomically. Throws RuntimeError("PATH: reason") on failure
// (missing directory, permission denied, disk full); the temporary file is removed.
void write_file_atomic(const std::string& path, std::string_view bytes);

}  // namespace inkshade::io
