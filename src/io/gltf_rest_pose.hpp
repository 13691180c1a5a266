// A glTF file's rest pose: every node's local transform as the file writes it (no animation)
// and its world matrix, as three-vrm captures them when it loads an avatar or a VRM animation
// (the rest rotations its humanoid rig, look-at and node constraints are relative to).
#pragma once
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace inkshade::io {

// The rotation of a matrix as three.js's Matrix4.decompose finds it: the columns divided by
// their lengths (the first negated when the determinant is negative), as a unit quaternion.
glm::dquat rotation_of(const glm::dmat4& m);

struct GltfRestPose {
    std::vector<int> parent;           // -1: a root (or a node no other node lists as a child)
    std::vector<glm::dmat4> world;     // rest world matrices
    std::vector<glm::dquat> rotation;  // rest local rotations (of the matrix, for a node with one)

    // The rest world rotation of the node's parent (identity for a root), three-vrm's
    // "parent world rotation".
    glm::dquat parent_world_rotation(size_t node) const {
        return parent[node] < 0 ? glm::dquat(1.0, 0.0, 0.0, 0.0) : rotation_of(world[size_t(parent[node])]);
    }
};

// The rest pose from each node's local transform (`local(i)`, the file's) and the parents.
// Nodes deeper than `max_depth` or in a cycle keep the world of the part of the chain below it.
template <class Local>
GltfRestPose gltf_rest_pose(const std::vector<int>& parent, Local local) {
    GltfRestPose rest;
    rest.parent = parent;
    const size_t n = parent.size();
    rest.world.assign(n, glm::dmat4(1.0));
    rest.rotation.resize(n);
    std::vector<char> done(n, 0);
    for (size_t i = 0; i < n; ++i) {
        std::vector<size_t> chain;  // i and its ancestors whose worlds are not known yet
        for (int at = int(i); at >= 0 && !done[size_t(at)] && chain.size() <= n; at = parent[size_t(at)])
            chain.push_back(size_t(at));
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            const glm::dmat4 l = local(*it);
            const int p = parent[*it];
            rest.world[*it] = (p >= 0 && done[size_t(p)] ? rest.world[size_t(p)] : glm::dmat4(1.0)) * l;
            rest.rotation[*it] = rotation_of(l);
            done[*it] = 1;
        }
    }
    return rest;
}

}  // namespace inkshade::io
