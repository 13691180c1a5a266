// three.js scene JSON (render --scene): parse_threejs_scene + threejs_scene_style; see scene_target.hpp.
#include "scene_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    inkshade::fuzz::scene_input({reinterpret_cast<const char*>(data), size});
    return 0;
}
