// `inkshade view --script` files: parse_script; see view_script_target.hpp.
#include "view_script_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    inkshade::fuzz::view_script_input({reinterpret_cast<const char*>(data), size});
    return 0;
}
