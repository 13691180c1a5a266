// Loading, then welding, normals, adjacency, curvature and line extraction with visibility on
// whatever a loader accepts; see mesh_pipeline_input in mesh_targets.hpp.
#include "mesh_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    inkshade::fuzz::mesh_pipeline_input({reinterpret_cast<const char*>(data), size});
    return 0;
}
