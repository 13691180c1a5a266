// Skinned meshes (glTF 2.0 section 3.7.3): linear blend skinning on the CPU, as three.js's
// skinning shader computes it, so that normals, lines and shading all see the posed triangles.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "io/gltf_accessors.hpp"

namespace inkshade::io {

// Skin weights made to sum to 1 as three.js's SkinnedMesh.normalizeSkinWeights does: each
// vertex's four weights divided by the sum of their magnitudes; a vertex whose weights are all
// zero is bound to its first joint alone.
void normalize_skin_weights(std::vector<float>& weights);

// Linear blend skinning (Magnenat-Thalmann, Laperrière and Thalmann 1988, "Joint-dependent local
// deformations for hand animation and object grasping"): each position becomes
// sum_k w_k M[j_k] p, with M[j] = world(joint j) x inverseBindMatrix(j); each normal the blended
// matrix's linear part times n, normalised (three.js's skinnormal chunk). `positions` and
// `normals` (empty or as many) hold xyz triples, `joints` and `weights` four values a vertex
// (JOINTS_0, WEIGHTS_0, the weights normalised already). A joint index past `joint_matrices`
// with a non-zero weight is an InputError through `reader`, naming the primitive `where` and
// the skin.
void skin_vertices(std::vector<float>& positions, std::vector<float>& normals, const std::vector<float>& joints,
                   const std::vector<float>& weights, const std::vector<glm::dmat4>& joint_matrices,
                   const std::string& where, int skin, const GltfFloatReader& reader);

}  // namespace inkshade::io
