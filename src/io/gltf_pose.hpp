// The pose a glTF/VRM file is read in (LoadOptions::pose): node transforms with an animation's
// values in place of the file's (a glTF animation, or a .vrma retargeted to the VRM humanoid with
// its look-at), then VRM node constraints, morph weights (the file's, the animation's, VRM
// expressions', then by name), and the skins that follow the joints. read_gltf asks it for each node's local
// transform and lets it deform each primitive before the primitive joins the mesh.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "inkshade/io.hpp"
#include "io/gltf_accessors.hpp"
#include "io/gltf_animation.hpp"
#include "io/gltf_rest_pose.hpp"
#include "io/pose_nodes.hpp"

namespace tinygltf {
class Model;
struct Node;
struct Primitive;
}  // namespace tinygltf

namespace inkshade::io {

class GltfPose final : private PoseNodes {
public:
    // The file's local transform of a node (matrix or T x R x S), checked; read_gltf's.
    using FileTransform = glm::dmat4 (*)(const tinygltf::Node& node, size_t index, const std::string& path);

    // Samples the animation, reads the expressions and sets the morph weights. Throws
    // InputError(path, ...) for an animation, expression or morph target name the file does not
    // have (listing those it has), and for a bad animation.
    GltfPose(const tinygltf::Model& model, const std::string& path, const Pose& pose, const GltfFloatReader& reader,
             FileTransform file_transform, std::vector<std::string>& warnings);

    // The node's local transform: the file's, with the animation's translation, rotation and
    // scale where it sets them, and the spring bones' rotation where a joint turns it.
    glm::dmat4 local(size_t node) const;

    // Deforms one primitive of the mesh node `node` instances, in place: its morph targets with
    // the node's weights, then, for a skinned node, linear blend skinning by the skin's joints
    // (positions and normals are then in world space). Throws InputError for a skin that refers
    // to nodes or accessors the file does not have, or a primitive without JOINTS_0 and WEIGHTS_0.
    void deform(size_t node, const tinygltf::Primitive& primitive, std::vector<float>& positions,
                std::vector<float>& normals, const std::string& where) const;

    // The node's world transform: its parents' local transforms and its own.
    glm::dmat4 world(size_t node) const override;
    // The morph weights of the node's mesh in this pose (empty: none).
    const std::vector<float>& morph_weights(size_t node) const { return weights_[node]; }

private:
    glm::dquat rotation(size_t node) const override;
    void set_rotation(size_t node, const glm::dquat& q) override;
    void set_translation(size_t node, const glm::dvec3& t) override;
    // The file's rest pose, computed when a VRM step first needs it.
    const GltfRestPose& rest() const;
    const std::vector<glm::dmat4>& joint_matrices(int skin) const;

    const tinygltf::Model& model_;
    const std::string& path_;
    const GltfFloatReader& reader_;
    FileTransform file_transform_;
    std::vector<AnimatedNode> animated_;       // empty: no animation
    std::vector<std::vector<float>> weights_;  // morph weights per node (empty: none)
    std::vector<int> parent_;                  // -1: a root
    mutable std::optional<GltfRestPose> rest_;
    std::vector<std::optional<glm::dquat>> spring_;  // rotations spring bones give (empty: none)
    mutable std::vector<std::optional<glm::dmat4>> world_;
    mutable std::map<int, std::vector<glm::dmat4>> joint_matrices_;
};

}  // namespace inkshade::io
