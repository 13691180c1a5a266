// PLY (ascii, both binary byte orders, TextureFile textures) through load_mesh; see ply_input.
#include "mesh_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    inkshade::fuzz::ply_input({reinterpret_cast<const char*>(data), size});
    return 0;
}
