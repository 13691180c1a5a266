// Whether a model file is drawn with MToon materials: a VRM (1.0 VRMC_vrm or 0.x VRM) or a glTF
// whose materials use VRMC_materials_mtoon. Read from the file's JSON alone (a GLB's first
// chunk), before the model loads, so that the request path can pick the look the file is
// authored for (docs/mtoon.md, "One command").
#pragma once
#include <string>

namespace inkshade::io {

// True for a .gltf, .glb or .vrm file whose extensionsUsed (or top-level extensions) names
// VRMC_vrm, VRM or VRMC_materials_mtoon. False for every other file, and for one that cannot be
// read or parsed: the loader reports those when the model loads.
bool uses_mtoon_materials(const std::string& path);

}  // namespace inkshade::io
