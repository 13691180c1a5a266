// A pose's nodes as the VRM steps after the animation read and write them (the humanoid rig,
// look-at and node constraints; GltfPose implements it): local rotations and translations over
// the file's, and world matrices that follow every change.
#pragma once
#include <cstddef>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace inkshade::io {

class PoseNodes {
public:
    virtual glm::dquat rotation(size_t node) const = 0;  // local
    virtual void set_rotation(size_t node, const glm::dquat& q) = 0;
    virtual void set_translation(size_t node, const glm::dvec3& t) = 0;
    virtual glm::dmat4 world(size_t node) const = 0;

protected:
    ~PoseNodes() = default;
};

}  // namespace inkshade::io
