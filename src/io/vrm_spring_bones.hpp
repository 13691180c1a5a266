// VRM spring bones as a file declares them: VRMC_springBone 1.0 (springs of joints, colliders,
// collider groups) and VRM 0.x secondary animation (extensions.VRM.secondaryAnimation: bone
// groups whose roots' descendants are all joints, sphere collider groups), read into one form as
// three-vrm 3.5.5's VRMSpringBoneLoaderPlugin (_v1Import, _v0Import) builds its joints.
// spring_bone_simulation.hpp moves them.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tinygltf {
class Model;
}

namespace inkshade::io {

// A sphere (capsule = false) or capsule collider on a node, in the node's space.
struct SpringCollider {
    int node = -1;
    bool capsule = false;
    glm::dvec3 offset{0.0}, tail{0.0};  // the sphere's centre / the capsule's two ends
    double radius = 0.0;
};

// One joint: the node it turns and the node whose position is its tail (-1: none, a VRM 0.x
// leaf, whose tail is 7 cm along its own offset from its parent), with three-vrm's defaults.
struct SpringJoint {
    int node = -1, child = -1;
    double hit_radius = 0.0, stiffness = 1.0, gravity_power = 0.0, drag_force = 0.4;
    glm::dvec3 gravity_dir{0.0, -1.0, 0.0};
    std::vector<int> colliders;  // indices into SpringBones::colliders, its collider groups' in order
    int center = -1;             // the node whose space the tail moves in; -1: world space
};

struct SpringBones {
    std::vector<SpringJoint> joints;  // in file order (three-vrm's insertion order)
    std::vector<SpringCollider> colliders;
    bool empty() const { return joints.empty(); }
};

// Most joints a file may have (a VRM 0.x bone group makes a joint of every node below its roots).
constexpr size_t kMaxSpringJoints = 10000;

// The file's spring bones: VRMC_springBone where extensionsUsed lists it (specVersion "1.0" or
// "1.0-beta"), else VRM 0.x secondaryAnimation where extensionsUsed lists "VRM"; none otherwise.
// Throws InputError(path, ...) for a node, collider or collider group index out of range, a value
// that is not a finite number, a negative radius, stiffness or gravity power, a drag force outside
// [0, 1], or more than kMaxSpringJoints joints. A collider without a shape is skipped with a
// warning (as three-vrm does).
SpringBones read_vrm_spring_bones(const tinygltf::Model& model, const std::string& path,
                                  std::vector<std::string>& warnings);

}  // namespace inkshade::io
