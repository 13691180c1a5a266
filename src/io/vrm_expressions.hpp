// VRM expressions (facial expressions: VRM 1.0 VRMC_vrm.expressions, VRM 0.x
// blendShapeMaster.blendShapeGroups) as three-vrm reads and applies them: each expression binds
// morph targets of some nodes with weights, and its weight in [0, 1] scales them. Material
// colour and texture-transform binds are not read.
#pragma once
#include <string>
#include <vector>

#include "inkshade/io.hpp"

namespace tinygltf {
class Model;
}

namespace inkshade::io {

// How an active expression damps the blink, look-at or mouth expressions (VRM 1.0 override*).
enum class ExpressionOverride { None, Block, Blend };

struct VrmExpression {
    std::string name;     // a VRM 1.0 preset name (happy, aa, blink, ...) or a custom name
    bool binary = false;  // isBinary: weights above 0.5 act as 1, others as 0
    ExpressionOverride blink = ExpressionOverride::None, look_at = ExpressionOverride::None,
                       mouth = ExpressionOverride::None;
    struct Bind {
        int node;      // a node instancing a mesh
        int target;    // morph target index of that mesh
        float weight;  // in [0, 1] (VRM 0.x's 0..100 scaled by 0.01, as three-vrm does)
    };
    std::vector<Bind> binds;
};

// Whether `name` is a VRM 1.0 preset expression name (happy, blink, aa, ...).
bool is_vrm_preset(const std::string& name);

// The file's expressions: VRM 1.0's when the file has VRMC_vrm expressions, else VRM 0.x's; none
// for other files. VRM 0.x presets take their VRM 1.0 names (joy -> happy, a -> aa, ...), custom
// groups their name; a bind to a node without a mesh, or to a morph target the mesh does not
// have, is left out with a warning, as three-vrm does.
std::vector<VrmExpression> read_vrm_expressions(const tinygltf::Model& model, const std::string& path,
                                                std::vector<std::string>& warnings);

// Sets the morph weights of the nodes (node_weights[node], one per morph target of its mesh) as
// three-vrm's VRMExpressionManager.update does with these expression weights (others 0): every
// bound target is cleared, then each expression adds bind weight x its weight, binary
// expressions rounded, blink / look-at / mouth expressions damped by the overrides of the
// others. Throws InputError(path, ...) for a name the file does not have, listing its names.
void apply_vrm_expressions(const std::vector<VrmExpression>& expressions, const std::vector<NamedWeight>& weights,
                           std::vector<std::vector<float>>& node_weights, const std::string& path);

}  // namespace inkshade::io
