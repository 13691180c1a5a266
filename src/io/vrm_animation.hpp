// VRM animations (.vrma: a GLB with the VRMC_vrm_animation extension) as three-vrm-animation
// 3.5.5 reads and retargets them: a humanoid's bone rotations (and hips translation),
// expression weights and a look-at rotation, keyed on nodes of the .vrma's own skeleton.
// VRMAnimationLoaderPlugin turns each rotation into the normalized humanoid's terms (rest world
// rotations of the .vrma's bones), createVRMAnimationClip scales the hips translation by the
// avatar's hips height over the .vrma's and flips x and z for VRM 0.x avatars.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "inkshade/io.hpp"
#include "io/vrm_humanoid.hpp"

namespace inkshade::io {

// Whether Pose::animation names a .vrma file (ends in .vrma, any case) rather than an animation
// inside the model.
bool is_vrma_path(const std::string& animation);

// One moment of a .vrma's first animation, in the normalized humanoid's terms of the .vrma.
struct VrmAnimationSample {
    std::map<std::string, glm::dquat> rotations;  // human bone -> normalized rotation
    std::optional<glm::dvec3> hips;               // hips world position in the .vrma
    double rest_hips_height = 0.0;                // the .vrma's rest hips world y
    std::vector<NamedWeight> expressions;         // preset and custom expression weights
    std::optional<glm::dquat> look_at;            // the lookAt node's rotation
};

// A .vrma read once and sampled at any time (the spring bones sample it at every step).
class VrmAnimationClip {
public:
    // Reads `path`. Throws InputError(path, ...) for a file that cannot be read or is not a VRM
    // animation.
    explicit VrmAnimationClip(const std::string& path);
    ~VrmAnimationClip();
    VrmAnimationClip(VrmAnimationClip&&) noexcept;
    VrmAnimationClip& operator=(VrmAnimationClip&&) noexcept;

    // Its first animation at `time` (clamped to its keyframes). Throws InputError(path, ...) for
    // bad data.
    VrmAnimationSample sample(double time) const;

private:
    struct Data;
    std::unique_ptr<const Data> data_;
};

// The sample on an avatar's humanoid (createVRMAnimationHumanoidTracks): bones the avatar does
// not have are left out (listed in `skipped`), the hips position scaled by the avatar's rest hips
// height (`avatar_hips_height`) over the .vrma's; VRM 0.x avatars get x and z negated.
NormalizedPose retarget_vrm_animation(const VrmAnimationSample& sample, const VrmHumanoid& humanoid,
                                      double avatar_hips_height, std::vector<std::string>& skipped);

}  // namespace inkshade::io
