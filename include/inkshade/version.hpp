// The version of Inkshade, as `inkshade --version` prints it and batch metadata records it.
#pragma once

namespace inkshade {

// Keep in step with project(inkshade VERSION ...) in CMakeLists.txt.
inline constexpr const char* kVersion = "0.1.0";

}  // namespace inkshade
