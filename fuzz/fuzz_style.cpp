// Style files: parse_style, apply_override and the format_style round trip; see style_target.hpp.
#include "style_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    inkshade::fuzz::style_input({reinterpret_cast<const char*>(data), size});
    return 0;
}
