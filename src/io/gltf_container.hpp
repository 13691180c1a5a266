// The glTF container: a .gltf (JSON with .bin files or data: URIs) or GLB (.glb, .vrm) file
// loaded into tinygltf's Model, every guard applied before tinygltf sees the bytes (GLB header
// and chunk table, JSON nesting depth, sizes), buffers read only from regular files, images
// kept encoded for the material reader to decode. tinygltf is compiled in gltf_container.cpp.
#pragma once
#include <string>

namespace tinygltf {
class Model;
}

namespace inkshade::io {

// Loads `path` (GLB by its magic, JSON by its opening brace, else by the extension) into
// `model`, checks the asset version and refuses extensions that compress the geometry.
// Accessors and bufferViews are not yet checked: GltfAccessorReader does that as it reads.
// Throws InputError(path, problem).
void load_gltf_model(const std::string& path, tinygltf::Model& model);

// One-line, printable text of tinygltf's multi-line messages (which may quote file bytes) and
// of names from the file: the first non-empty line, at most 200 characters.
std::string printable_first_line(const std::string& s);

}  // namespace inkshade::io
