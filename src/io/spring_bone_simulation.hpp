// Spring bones moved through time as three-vrm 3.5.5 moves them (VRMSpringBoneManager.update,
// VRMSpringBoneJoint.update): Verlet integration of each joint's tail with drag, stiffness
// towards the rest direction and gravity, kept at the bone's length and pushed out of sphere and
// capsule colliders, in three-vrm's joint order and with its world matrices refreshed where it
// refreshes them. Deterministic: fixed steps of kSpringStep from the rest pose at t = 0 to the
// time asked for, the last step shortened to end there; at each step the animation's pose at the
// step's end drives the joints' parents (a three.js app's mixer.update, then vrm.update).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "io/vrm_spring_bones.hpp"

namespace inkshade::io {

// three.js's Object3D position, quaternion and scale of a node.
struct NodeTrs {
    glm::dvec3 t{0.0};
    glm::dquat r{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 s{1.0};
    bool rotation_animated = false;  // the animation sets r (it then replaces a joint's own)

    glm::dmat4 matrix() const {
        return glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(r) * glm::scale(glm::dmat4(1.0), s);
    }
};

// The step: 60 Hz.
constexpr double kSpringStep = 1.0 / 60.0;
// Most work one simulation may take: steps x (joints + nodes).
constexpr double kMaxSpringWork = 2e8;

// The ends of the steps from 0 to `time`: k x kSpringStep, the last one `time` itself (a step
// shorter than a microsecond is merged into the one before).
std::vector<double> spring_step_times(double time);

// Every node's local transform at a time: `nodes` holds the file's, with each joint's rotation
// from the step before; the function sets the animation's values at that time (and what the VRM
// steps before the springs set).
using NodePoseAt = std::function<void(double time, std::vector<NodeTrs>& nodes)>;

// The rotation of each joint's node at `time` (indexed by node; empty where no joint turns it).
// `parent[n]` is node n's parent (-1: a root); `rest` the file's pose, in which the joints start.
// Throws InputError(path, ...) where the steps would take more than kMaxSpringWork, or a joint,
// collider or center node lies in a cycle of the node hierarchy.
std::vector<std::optional<glm::dquat>> simulate_spring_bones(const SpringBones& bones, const std::vector<int>& parent,
                                                             const std::vector<NodeTrs>& rest,
                                                             const NodePoseAt& pose_at, double time,
                                                             const std::string& path);

}  // namespace inkshade::io
