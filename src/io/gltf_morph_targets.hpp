// Morph targets (glTF 2.0 section 3.7.2.2): per-vertex displacements of positions and normals,
// added with weights. Names come from mesh.extras.targetNames, where three.js's GLTFLoader
// reads them (the specification leaves names to extras).
#pragma once
#include <string>
#include <vector>

#include "io/gltf_accessors.hpp"

namespace tinygltf {
class Model;
struct Mesh;
struct Primitive;
}  // namespace tinygltf

namespace inkshade::io {

// The mesh's number of morph targets (its first primitive's: every primitive has as many).
size_t morph_target_count(const tinygltf::Mesh& mesh);

// mesh.extras.targetNames, one per target; a missing or non-string name is empty.
std::vector<std::string> morph_target_names(const tinygltf::Mesh& mesh);

// The mesh's default weights (mesh.weights), one per target (zeros where it gives none).
std::vector<float> default_morph_weights(const tinygltf::Mesh& mesh);

// Adds sum_i weights[i] x target_i to the primitive's positions and normals (xyz triples; normals
// may be empty), as three.js does with the relative targets glTF stores. Targets of weight zero
// are not read. A target whose accessors have another element count is an InputError.
void apply_morph_targets(const tinygltf::Primitive& primitive, const std::vector<float>& weights,
                         std::vector<float>& positions, std::vector<float>& normals, const std::string& where,
                         const GltfFloatReader& reader);

}  // namespace inkshade::io
