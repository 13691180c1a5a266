// glTF animations (glTF 2.0 section 3.11 and Appendix C): keyframe tracks of node translation,
// rotation, scale and morph target weights, sampled at one time.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "io/gltf_accessors.hpp"

namespace tinygltf {
class Model;
}

namespace inkshade::io {

enum class Interpolation { Step, Linear, CubicSpline };

// The value of a keyframe track at time t. `times` ascend (n keys); `values` hold n x components
// numbers, or for CubicSpline 3n x components: per key its in-tangent, value and out-tangent.
// Before the first key the first value holds, after the last the last. With `quaternion`
// (rotations, components 4 as x, y, z, w) Linear is a spherical interpolation along the shorter
// arc (three.js's QuaternionLinearInterpolant) and the result is normalised.
std::vector<double> sample_keyframes(const std::vector<float>& times, const std::vector<float>& values,
                                     size_t components, Interpolation interpolation, double t, bool quaternion);

// What an animation sets on one node at the sampled time; unset: the node's own value.
struct AnimatedNode {
    std::optional<glm::dvec3> translation, scale;
    std::optional<glm::dquat> rotation;
    std::optional<std::vector<float>> weights;  // morph target weights of the node's mesh
};

// The animation of `model` that `name` names (its name, else its index as digits). Throws
// InputError(path, ...) for an unknown one, listing the file's animations.
int find_gltf_animation(const tinygltf::Model& model, const std::string& name, const std::string& path);

// Animation `index` sampled at `time` seconds, clamped to the range of its keyframes: one entry
// per node of the model. Channels of unknown paths (extensions) are skipped; a channel or
// sampler that refers to nothing, or accessors of the wrong shape, are InputErrors.
std::vector<AnimatedNode> sample_gltf_animation(const tinygltf::Model& model, int index, double time,
                                                const GltfFloatReader& reader);

}  // namespace inkshade::io
