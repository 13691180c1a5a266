// glTF 2.0 JSON (.gltf) and GLB (.glb) through load_mesh; see gltf_input in mesh_targets.hpp.
#include "mesh_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    inkshade::fuzz::gltf_input({reinterpret_cast<const char*>(data), size});
    return 0;
}
