// STL, ASCII and binary, through load_mesh; see stl_input in mesh_targets.hpp.
#include "mesh_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    inkshade::fuzz::stl_input({reinterpret_cast<const char*>(data), size});
    return 0;
}
