#include "io/node_trs_frame.hpp"

namespace inkshade::io {

void NodeTrsFrame::set_rotation(size_t node, const glm::dquat& q) {
    nodes_[node].r = q;
    nodes_[node].rotation_animated = true;
    world_.assign(world_.size(), std::nullopt);  // every world below the node changes
}

void NodeTrsFrame::set_translation(size_t node, const glm::dvec3& t) {
    nodes_[node].t = t;
    world_.assign(world_.size(), std::nullopt);
}

glm::dmat4 NodeTrsFrame::world(size_t node) const {
    if (world_[node]) return *world_[node];
    std::vector<size_t> chain;  // node, its parent, ... up to a node whose world is known or a root
    // A cycle of parents (which reading the pose has already refused) ends the walk.
    for (int at = int(node); at >= 0 && !world_[size_t(at)] && chain.size() <= nodes_.size(); at = parent_[size_t(at)])
        chain.push_back(size_t(at));
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        const int p = parent_[*it];
        const glm::dmat4 above = p >= 0 && world_[size_t(p)] ? *world_[size_t(p)] : glm::dmat4(1.0);
        world_[*it] = above * nodes_[*it].matrix();
    }
    return *world_[node];
}

}  // namespace inkshade::io
