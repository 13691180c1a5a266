// Spring bones against three-vrm 3.5.5, as tests/reference/spring_bones.mjs has three-vrm place
// them (the same 1/60 s steps), each node within 1e-3 of the avatar's height:
// - the sample avatar's ponytail (scripts/avatar-sample --spring-hair: four joints, a sphere
//   collider on the head and a capsule on the back, gravity) swinging while the animation "sway"
//   tilts the head, at 0.5 s, 1 s and 2 s (tilted back, the ponytail on the capsule);
// - the rig avatar's hair (vrm_spring_rig_files.hpp) under a .vrma that turns the head (the
//   chain's root's parent) and, through a rotation constraint, the other chain's root's parent,
//   and under a glTF animation that turns the head; the hair must also hang measurably
//   otherwise than the springs left at rest would have it (what a .vrma or constraint that did
//   not drive the springs gives).
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <memory>

#include <nlohmann/json.hpp>

#include "inkshade/io.hpp"
#include "io/vrm_spring_rig_files.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

std::string run(const std::string& command) {
    std::string out;
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    if (!pipe) return out;
    char buffer[4096];
    for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe.get())) > 0;) out.append(buffer, n);
    return out;
}

TEST(SpringBonesReference, PonytailMatchesThreeVrm) {
    TempDir dir;
    const std::string avatar = dir.file("ponytail.vrm"), source = INKSHADE_SOURCE_DIR;
    ASSERT_EQ(std::system(("python3 '" + source + "/scripts/avatar-sample' --spring-hair '" + avatar + "'").c_str()),
              0);
    const std::string text =
        run("cd '" + source + "/tests/reference' && node spring_bones.mjs '" + avatar + "' sway 0.5 1 2 2>/dev/null");
    const nlohmann::json reference = nlohmann::json::parse(text, nullptr, false);
    ASSERT_TRUE(reference.is_object()) << "tests/reference/spring_bones.mjs (scripts/setup installs three-vrm): "
                                       << text;
    const BoundingBox box = load_mesh(avatar).bounds();
    const double height = box.max.y - box.min.y;
    for (const char* time : {"0.5", "1", "2"}) {
        Pose pose{.animation = "sway", .time = std::stof(time)};
        double worst = 0.0;
        size_t ponytail = 0;
        for (const PosedNode& node : posed_nodes(avatar, pose)) {
            ASSERT_TRUE(reference[time].contains(node.name)) << node.name;
            const auto& p = reference[time][node.name];
            const glm::dvec3 want(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
            worst = std::max(worst, glm::length(node.position - want) / height);
            ponytail += node.name.starts_with("Ponytail");
        }
        EXPECT_EQ(ponytail, 5u);
        EXPECT_LT(worst, 1e-3) << "at " << time << " s";
        std::printf("spring bones vs three-vrm at %s s: largest joint error %.3g of the height\n", time, worst);
    }
}

using Positions = std::map<std::string, glm::dvec3>;

constexpr double kRigHeight = 1.62;  // the rig avatar's eyes
constexpr double kTolerance = 1e-3 * kRigHeight;

Positions inkshade_positions(const std::string& avatar, const Pose& pose) {
    Positions out;
    for (const PosedNode& node : posed_nodes(avatar, pose)) out[node.name] = node.position;
    return out;
}

// The largest distance between the two poses' nodes (every node must be in both).
double worst_error(const Positions& ours, const nlohmann::json& theirs) {
    double worst = 0.0;
    for (const auto& [name, p] : ours) {
        EXPECT_TRUE(theirs.contains(name)) << name;
        if (!theirs.contains(name)) continue;
        const auto& t = theirs[name];
        const glm::dvec3 want(t[0].get<double>(), t[1].get<double>(), t[2].get<double>());
        EXPECT_LT(glm::length(p - want), kTolerance) << name << ": ours " << p.x << " " << p.y << " " << p.z
                                                     << ", three-vrm " << want.x << " " << want.y << " " << want.z;
        worst = std::max(worst, glm::length(p - want));
    }
    return worst;
}

// How differently the chain `name` (joints name2 ... name4) hangs from `anchors` (nodes fixed
// to its root's parent) in three-vrm's pose and in `at_rest`: the largest change of a distance
// from a joint to an anchor. Springs that the animation does not drive keep at_rest's shape
// relative to the anchors, so this is a lower bound on their error.
double displacement(const nlohmann::json& theirs, const Positions& at_rest, const std::string& name,
                    const std::vector<std::string>& anchors) {
    auto theirs_at = [&](const std::string& n) {
        const auto& t = theirs[n];
        return glm::dvec3(t[0].get<double>(), t[1].get<double>(), t[2].get<double>());
    };
    double most = 0.0;
    for (int k = 2; k <= 4; ++k) {
        const std::string joint = name + std::to_string(k);
        for (const std::string& a : anchors)
            most = std::max(most, std::abs(glm::length(theirs_at(joint) - theirs_at(a)) -
                                           glm::length(at_rest.at(joint) - at_rest.at(a))));
    }
    return most;
}

// The rig avatar with hair under `animation` (a .vrma path or "nod") at 0.5 s and 2 s against
// three-vrm; each chain in `driven` must hang measurably otherwise than with the springs at rest.
void check_rig_hair(const std::string& animation, const std::string& label,
                    const std::map<std::string, std::vector<std::string>>& driven) {
    TempDir dir;
    const std::string avatar = dir.write("hair.vrm", rig_avatar_with_hair().glb()), source = INKSHADE_SOURCE_DIR;
    const std::string clip = animation == "clip.vrma" ? dir.write("clip.vrma", rig_animation().glb()) : animation;
    const std::string text = run("cd '" + source + "/tests/reference' && node spring_bones.mjs '" + avatar + "' '" +
                                 clip + "' 0.5 2 2>/dev/null");
    const nlohmann::json reference = nlohmann::json::parse(text, nullptr, false);
    ASSERT_TRUE(reference.is_object()) << "tests/reference/spring_bones.mjs (scripts/setup installs three-vrm): "
                                       << text;
    for (const char* time : {"0.5", "2"}) {
        ASSERT_TRUE(reference.contains(time));
        const float t = std::stof(time);
        const double worst =
            worst_error(inkshade_positions(avatar, Pose{.animation = clip, .time = t}), reference[time]);
        const Positions at_rest = inkshade_positions(avatar, Pose{.time = t});
        for (const auto& [chain, anchors] : driven) {
            const double moved = displacement(reference[time], at_rest, chain, anchors);
            EXPECT_GT(moved, 10.0 * kTolerance) << chain << " at " << time << " s";
            std::printf("%s at %s s: %s hangs %.3g of the height otherwise than at rest\n", label.c_str(), time,
                        chain.c_str(), moved / kRigHeight);
        }
        std::printf("%s at %s s: largest node error %.3g of the height\n", label.c_str(), time, worst / kRigHeight);
    }
}

const std::vector<std::string> kHeadAnchors = {"J_head", "J_leftEye", "J_rightEye"};
const std::vector<std::string> kBaseAnchors = {"HairBase", "HairBaseTip", "BackHair1"};

TEST(SpringBonesReference, VrmaDrivesHairMatchesThreeVrm) {
    check_rig_hair("clip.vrma", "hair under a .vrma", {{"HeadHair", kHeadAnchors}, {"BackHair", kBaseAnchors}});
}

TEST(SpringBonesReference, ConstraintUnderGltfAnimationDrivesHairMatchesThreeVrm) {
    check_rig_hair("nod", "hair under a glTF animation", {{"HeadHair", kHeadAnchors}, {"BackHair", kBaseAnchors}});
}

}  // namespace
}  // namespace inkshade::test
