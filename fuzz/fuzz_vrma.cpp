// A VRM avatar posed by a VRM animation (.vrma) through load_mesh; see vrma_input in mesh_targets.hpp.
#include "mesh_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    inkshade::fuzz::vrma_input({reinterpret_cast<const char*>(data), size});
    return 0;
}
