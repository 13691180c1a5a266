// The nodes of one spring bone step (NodeTrs: three.js's position, quaternion and scale) as the
// VRM steps before the springs read and write them (PoseNodes: the humanoid rig, look-at and
// node constraints): world matrices follow the locals, and a rotation set there counts as the
// animation's (it then replaces a joint's own, as three-vrm's VRM.update sets it before the
// springs).
#pragma once
#include <optional>
#include <vector>

#include "io/pose_nodes.hpp"
#include "io/spring_bone_simulation.hpp"

namespace inkshade::io {

class NodeTrsFrame final : public PoseNodes {
public:
    // `nodes` and `parent` (-1: a root) must outlive the frame.
    NodeTrsFrame(std::vector<NodeTrs>& nodes, const std::vector<int>& parent)
        : nodes_(nodes), parent_(parent), world_(nodes.size()) {}

    glm::dquat rotation(size_t node) const override { return nodes_[node].r; }
    void set_rotation(size_t node, const glm::dquat& q) override;
    void set_translation(size_t node, const glm::dvec3& t) override;
    glm::dmat4 world(size_t node) const override;

private:
    std::vector<NodeTrs>& nodes_;
    const std::vector<int>& parent_;
    mutable std::vector<std::optional<glm::dmat4>> world_;  // computed when asked; cleared on a change
};

}  // namespace inkshade::io
