// VRM animations, look-at and node constraints against three-vrm 3.5.5 itself: the avatars and
// the .vrma of vrm_rig_files.hpp posed by tests/reference/vrm_pose.mjs (three.js's
// AnimationMixer, three-vrm-animation's createVRMAnimationClip, VRM.update) in node, and by
// posed_nodes; every node's world position must agree within 1e-4 of the avatar's height and
// every morph weight within 1e-4. Needs node and tests/reference/node_modules (scripts/setup).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "inkshade/io.hpp"
#include "io/vrm_rig_files.hpp"
#include "support/temp_dir.hpp"

namespace inkshade {
namespace {

using test::rig_animation;
using test::rig_avatar;

constexpr double kHeight = 1.62;  // the avatars' eyes
constexpr double kPositionTolerance = 1e-4 * kHeight, kWeightTolerance = 1e-4;

const test::TempDir& work_dir() {
    static const test::TempDir dir;  // removed when the test binary exits
    return dir;
}

std::string write_file(const std::string& name, const std::string& bytes) { return work_dir().write(name, bytes); }

// three-vrm's poses at `times` (comma-separated) as vrm_pose.mjs prints them.
nlohmann::json three_vrm_poses(const std::string& avatar, const std::string& clip, const std::string& times,
                               const std::string& expressions = "") {
    const std::string command = "node '" INKSHADE_SOURCE_DIR "/tests/reference/vrm_pose.mjs' '" + avatar + "' '" +
                                clip + "' " + times + " " + expressions + " 2>'" + work_dir().file("node.log") + "'";
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return {};
    std::string out;
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
    const int status = ::pclose(pipe);
    if (status != 0) {
        std::ifstream log(work_dir().file("node.log"));
        ADD_FAILURE() << command << " failed:\n" << std::string(std::istreambuf_iterator<char>(log), {});
        return {};
    }
    return nlohmann::json::parse(out);
}

struct MaxError {
    double position = 0.0, weight = 0.0;
};

// Inkshade's pose of `avatar` against three-vrm's `theirs` (one time), node by node.
void compare(const std::string& avatar, const Pose& pose, const nlohmann::json& theirs, MaxError& max) {
    const std::vector<PosedNode> ours = posed_nodes(avatar, pose);
    ASSERT_EQ(ours.size(), theirs["nodes"].size());
    for (size_t i = 0; i < ours.size(); ++i) {
        const nlohmann::json& t = theirs["nodes"][i];
        SCOPED_TRACE("node " + std::to_string(i) + " '" + ours[i].name + "' at t = " + std::to_string(pose.time));
        EXPECT_EQ(ours[i].name, t["name"].get<std::string>());
        const glm::dvec3 p(t["position"][0], t["position"][1], t["position"][2]);
        const double d = glm::length(ours[i].position - p);
        max.position = std::max(max.position, d);
        EXPECT_LT(d, kPositionTolerance) << "ours " << ours[i].position.x << " " << ours[i].position.y << " "
                                         << ours[i].position.z << ", three-vrm " << p.x << " " << p.y << " " << p.z;
        ASSERT_EQ(ours[i].morph_weights.size(), t["weights"].size());
        for (size_t k = 0; k < ours[i].morph_weights.size(); ++k) {
            const double e = std::abs(double(ours[i].morph_weights[k]) - t["weights"][k].get<double>());
            max.weight = std::max(max.weight, e);
            EXPECT_LT(e, kWeightTolerance) << "morph " << k;
        }
    }
}

void check_against_three_vrm(bool v0, const std::string& clip_name, const std::vector<NamedWeight>& expressions,
                             const char* label, bool other_look_at = false) {
    const std::string avatar = write_file(v0 ? "rig0.vrm" : "rig1.vrm", rig_avatar(v0, other_look_at).glb());
    const std::string clip = clip_name.empty() ? "-" : write_file(clip_name, rig_animation().glb());
    std::string args;
    for (const NamedWeight& e : expressions) args += " " + e.name + "=" + std::to_string(e.weight);
    const nlohmann::json theirs = three_vrm_poses(avatar, clip, "0.3,1.2", args);
    ASSERT_EQ(theirs.size(), 2u);
    MaxError max;
    for (const nlohmann::json& at : theirs) {
        Pose pose{.animation = clip == "-" ? "" : clip, .time = at["time"].get<float>(), .expressions = expressions};
        compare(avatar, pose, at, max);
    }
    std::printf("%s: max position error %.3g m (%.3g x height), max weight error %.3g\n", label, max.position,
                max.position / kHeight, max.weight);
}

TEST(VrmAnimationReference, Vrm1AvatarMatchesThreeVrm) {
    check_against_three_vrm(false, "clip.vrma", {{"aa", 0.7f}}, "VRM 1.0 avatar, .vrma");
}

TEST(VrmAnimationReference, Vrm0AvatarMatchesThreeVrm) {
    check_against_three_vrm(true, "clip.vrma", {}, "VRM 0.x avatar, .vrma");
}

// The other look-at types: VRM 1.0 expression (lookUp ... lookRight), VRM 0.x bone (eyes facing -z).
TEST(VrmAnimationReference, OtherLookAtTypesMatchThreeVrm) {
    check_against_three_vrm(false, "clip.vrma", {{"lookLeft", 1.0f}}, "VRM 1.0 avatar, expression look-at", true);
    check_against_three_vrm(true, "clip.vrma", {}, "VRM 0.x avatar, bone look-at", true);
}

TEST(VrmAnimationReference, ConstraintsWithoutAnimationMatchThreeVrm) {
    check_against_three_vrm(false, "", {{"happy", 0.6f}}, "VRM 1.0 avatar, constraints at rest");
}

}  // namespace
}  // namespace inkshade
