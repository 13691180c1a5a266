// Batch manifests (CSV, JSON Lines): parse_manifest; see manifest_target.hpp.
#include "manifest_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    inkshade::fuzz::manifest_input({reinterpret_cast<const char*>(data), size});
    return 0;
}
