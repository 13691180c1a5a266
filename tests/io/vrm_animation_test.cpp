// VRM animations (.vrma), look-at and node constraints on analytic cases (the pose a rotation of
// the normalized humanoid must give, whatever the bones' rest rotations), and bad input: every
// problem is one InputError, never a crash.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <optional>
#include <string>

#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "io/gltf_rest_pose.hpp"
#include "io/vrm_animation.hpp"
#include "io/vrm_look_at.hpp"
#include "io/vrm_node_constraints.hpp"
#include "io/vrm_rig_files.hpp"
#include "support/temp_dir.hpp"

namespace inkshade {
namespace {

using namespace inkshade::test;

// Files of the running test (removed after it).
class VrmFiles : public ::testing::Test {
protected:
    std::string write_file(const std::string& name, const std::string& bytes) { return dir_.write(name, bytes); }
    TempDir dir_;
};

// A .vrma of the avatar's bones at rest rotation identity (hips at y = 0.9), keying one bone's
// rotation and optionally the hips' translation at t = 0 and 1.
GltfBuilder one_bone_clip(const std::string& bone, const glm::dquat& rotation,
                          std::optional<glm::dvec3> hips = std::nullopt) {
    GltfBuilder g;
    const int root = g.node({{"name", "Root"}});
    std::vector<RigBone> bones = avatar_rig_bones();
    for (RigBone& b : bones) {
        b.degrees = 0.0;
        b.world.y *= 0.9;
    }
    const std::map<std::string, int> nodes = add_rig(g, bones, root, glm::dmat4(1.0));
    nlohmann::json animation = {{"samplers", nlohmann::json::array()}, {"channels", nlohmann::json::array()}};
    add_track(g, animation, nodes.at(bone), "rotation", {0, 1},
              {0, 0, 0, 1, float(rotation.x), float(rotation.y), float(rotation.z), float(rotation.w)}, "VEC4");
    if (hips) {
        const glm::dvec3 rest = bones[0].world;
        add_track(g, animation, nodes.at("hips"), "translation", {0, 1},
                  {float(rest.x), float(rest.y), float(rest.z), float(hips->x), float(hips->y), float(hips->z)},
                  "VEC3");
    }
    g.doc["animations"] = {animation};
    g.scene({root});
    nlohmann::json human = nlohmann::json::object();
    for (const auto& [name, node] : nodes) human[name] = {{"node", node}};
    g.doc["extensionsUsed"] = {"VRMC_vrm_animation"};
    g.doc["extensions"]["VRMC_vrm_animation"] = {{"specVersion", "1.0"}, {"humanoid", {{"humanBones", human}}}};
    return g;
}

glm::dvec3 node_position(const std::vector<PosedNode>& nodes, const std::string& name) {
    for (const PosedNode& n : nodes)
        if (n.name == name) return n.position;
    ADD_FAILURE() << "no node " << name;
    return glm::dvec3(0.0);
}

void expect_near(glm::dvec3 a, glm::dvec3 b, double tolerance = 1e-5) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(VrmAnimation, VrmaPathsAreTheOnesEndingInVrma) {
    EXPECT_TRUE(io::is_vrma_path("dance.vrma"));
    EXPECT_TRUE(io::is_vrma_path("a/B.VRMA"));
    EXPECT_FALSE(io::is_vrma_path("vrma"));
    EXPECT_FALSE(io::is_vrma_path("wave"));
    EXPECT_FALSE(io::is_vrma_path("0"));
}

// A quarter turn of the normalized left upper arm about +z raises the forearm about the
// shoulder in world axes, whatever the avatar's and the .vrma's rest rotations.
TEST_F(VrmFiles, NormalizedRotationTurnsTheBoneInWorldAxes) {
    const std::string avatar = write_file("arm1.vrm", rig_avatar(false).glb());
    const std::string clip = write_file("arm.vrma", one_bone_clip("leftUpperArm", axis_degrees({0, 0, 1}, 90)).glb());
    const std::vector<PosedNode> posed = posed_nodes(avatar, {.animation = clip, .time = 1.0f});
    expect_near(node_position(posed, "J_leftUpperArm"), glm::dvec3(0.2, 1.4, 0));
    expect_near(node_position(posed, "J_leftLowerArm"), glm::dvec3(0.2, 1.4 + 0.25, -0.01));
    expect_near(node_position(posed, "J_leftHand"), glm::dvec3(0.2, 1.4 + 0.5, 0));
    // Half way (t = 0.5) is half the angle: slerp.
    const std::vector<PosedNode> half = posed_nodes(avatar, {.animation = clip, .time = 0.5f});
    const double c = std::cos(glm::radians(45.0)) * 0.5, s = std::sin(glm::radians(45.0)) * 0.5;
    expect_near(node_position(half, "J_leftHand"), glm::dvec3(0.2 + c, 1.4 + s, 0));
}

// VRM 0.x avatars face -z: the same clip raises their left arm (at -x) as well.
TEST_F(VrmFiles, Vrm0AvatarsGetXAndZFlipped) {
    const std::string avatar = write_file("arm0.vrm", rig_avatar(true).glb());
    const std::string clip = write_file("arm.vrma", one_bone_clip("leftUpperArm", axis_degrees({0, 0, 1}, 90)).glb());
    const std::vector<PosedNode> posed = posed_nodes(avatar, {.animation = clip, .time = 1.0f});
    expect_near(node_position(posed, "J_leftHand"), glm::dvec3(-0.2, 1.4 + 0.5, 0));
}

// The hips move by the .vrma's translation scaled by the hips heights (1.0 / 0.9).
TEST_F(VrmFiles, HipsTranslationIsScaledByHipsHeight) {
    const std::string avatar = write_file("hips.vrm", rig_avatar(false).glb());
    const std::string clip =
        write_file("hips.vrma", one_bone_clip("spine", glm::dquat(1, 0, 0, 0), glm::dvec3(0.09, 0.45, -0.18)).glb());
    const std::vector<PosedNode> posed = posed_nodes(avatar, {.animation = clip, .time = 1.0f});
    expect_near(node_position(posed, "J_hips"), glm::dvec3(0.1, 0.5, -0.2));
}

// The clip's expression weights, then --expression (which wins for the same name).
TEST_F(VrmFiles, ExpressionsGivenOverrideTheClips) {
    const std::string avatar = write_file("face.vrm", rig_avatar(false).glb());
    const std::string clip = write_file("face.vrma", rig_animation().glb());
    auto happy = [&](const std::vector<NamedWeight>& expressions) {
        for (const PosedNode& n : posed_nodes(avatar, {.animation = clip, .time = 2.0f, .expressions = expressions}))
            if (n.name == "Face") return n.morph_weights[0];
        return -1.0f;
    };
    EXPECT_FLOAT_EQ(happy({}), 1.0f);  // the clip's last key
    EXPECT_FLOAT_EQ(happy({{"happy", 0.25f}}), 0.25f);
}

TEST_F(VrmFiles, BonesAndExpressionsTheAvatarLacksAreSkippedWithAWarning) {
    const std::string avatar = write_file("skip.vrm", rig_avatar(false).glb());
    const std::string clip = write_file("skip.vrma", rig_animation().glb());
    const Mesh mesh = load_mesh(avatar, {.pose = {.animation = clip, .time = 0.5f}});
    std::string warnings;
    for (const std::string& w : mesh.warnings) warnings += w + "\n";
    EXPECT_NE(warnings.find("upperChest"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("expression surprised"), std::string::npos) << warnings;
}

TEST(VrmLookAt, YawAndPitchAreTheYxzEulerAngles) {
    const glm::dquat q = axis_degrees({0, 1, 0}, 30) * axis_degrees({1, 0, 0}, -20);
    const glm::dvec2 yp = io::look_at_yaw_pitch(q);
    EXPECT_NEAR(yp.x, 30.0, 1e-9);
    EXPECT_NEAR(yp.y, -20.0, 1e-9);
}

TEST(VrmLookAt, RangeMapsScaleAndSaturate) {
    const io::VrmLookAt::RangeMap map{60.0, 20.0};
    EXPECT_DOUBLE_EQ(map.map(30.0), 10.0);
    EXPECT_DOUBLE_EQ(map.map(90.0), 20.0);
    EXPECT_DOUBLE_EQ(map.map(-5.0), 0.0);
    io::VrmLookAt look;
    look.expression = true;
    look.horizontal_outer = {40.0, 0.8};
    look.vertical_up = {35.0, 0.7};
    const std::vector<NamedWeight> w = io::look_at_expression_weights(look, {-20.0, -35.0});
    // Looking up-right (negative pitch and yaw): lookUp and lookRight.
    ASSERT_EQ(w.size(), 4u);
    EXPECT_EQ(w[1].name, "lookUp");
    EXPECT_FLOAT_EQ(w[1].weight, 0.7f);
    EXPECT_EQ(w[3].name, "lookRight");
    EXPECT_FLOAT_EQ(w[3].weight, 0.4f);
}

// Two root nodes (0: source at the origin, 1: destination) with rest rotations and current ones.
class FakeNodes final : public io::PoseNodes {
public:
    std::vector<glm::dquat> rotations;
    std::vector<glm::dvec3> positions;
    glm::dquat rotation(size_t n) const override { return rotations[n]; }
    void set_rotation(size_t n, const glm::dquat& q) override { rotations[n] = q; }
    void set_translation(size_t n, const glm::dvec3& t) override { positions[n] = t; }
    glm::dmat4 world(size_t n) const override {
        return glm::translate(glm::dmat4(1.0), positions[n]) * glm::mat4_cast(rotations[n]);
    }
};

glm::dquat constrained(io::VrmNodeConstraint c, const glm::dquat& source_now, const glm::dquat& dst_rest,
                       glm::dvec3 source_position = {}) {
    io::GltfRestPose rest;
    rest.parent = {-1, -1};
    rest.world = {glm::dmat4(1.0), glm::mat4_cast(dst_rest)};
    rest.rotation = {glm::dquat(1, 0, 0, 0), dst_rest};
    FakeNodes nodes;
    nodes.rotations = {source_now, dst_rest};
    nodes.positions = {source_position, glm::dvec3(0.0)};
    c.source = 0;
    c.destination = 1;
    const std::vector<io::VrmNodeConstraint> list = {c};
    io::apply_vrm_node_constraints(list, io::vrm_node_constraint_order(list, rest.parent, "f"), rest, nodes);
    return nodes.rotations[1];
}

void expect_same_rotation(const glm::dquat& a, const glm::dquat& b) {
    EXPECT_NEAR(std::abs(glm::dot(a, b)), 1.0, 1e-9) << "(" << a.w << " " << a.x << " " << a.y << " " << a.z << ") vs ("
                                                     << b.w << " " << b.x << " " << b.y << " " << b.z << ")";
}

TEST(VrmNodeConstraints, RotationCopiesTheSourcesTurnByWeight) {
    const glm::dquat rest = axis_degrees({1, 0, 0}, 30), turn = axis_degrees({0, 1, 0}, 80);
    io::VrmNodeConstraint c{.kind = io::VrmNodeConstraint::Kind::Rotation};
    expect_same_rotation(constrained(c, turn, rest), rest * turn);
    c.weight = 0.5;
    expect_same_rotation(constrained(c, turn, rest), rest * axis_degrees({0, 1, 0}, 40));
}

TEST(VrmNodeConstraints, RollKeepsOnlyTheTwistAboutTheAxis) {
    const glm::dquat turn = axis_degrees({0, 1, 0}, 30) * axis_degrees({1, 0, 0}, 60);
    io::VrmNodeConstraint c{.kind = io::VrmNodeConstraint::Kind::Roll, .axis = {1, 0, 0}};
    expect_same_rotation(constrained(c, turn, glm::dquat(1, 0, 0, 0)), axis_degrees({1, 0, 0}, 60));
}

TEST(VrmNodeConstraints, AimTurnsTheAxisToTheSource) {
    io::VrmNodeConstraint c{.kind = io::VrmNodeConstraint::Kind::Aim, .axis = {1, 0, 0}};
    const glm::dquat q = constrained(c, glm::dquat(1, 0, 0, 0), glm::dquat(1, 0, 0, 0), {0, 0, 2});
    const glm::dvec3 x = q * glm::dvec3(1, 0, 0);
    EXPECT_NEAR(x.z, 1.0, 1e-12);
}

TEST(VrmNodeConstraints, DependenciesComeFirstAndCyclesAreErrors) {
    using K = io::VrmNodeConstraint::Kind;
    const std::vector<int> parent = {-1, -1, -1};
    // 0 reads node 2, which constraint 1 turns: constraint 1 runs first.
    std::vector<io::VrmNodeConstraint> list = {{K::Rotation, 0, 2, {1, 0, 0}, 1.0},
                                               {K::Rotation, 2, 1, {1, 0, 0}, 1.0}};
    EXPECT_EQ(io::vrm_node_constraint_order(list, parent, "f"), (std::vector<size_t>{1, 0}));
    list[1].source = 0;  // 0 reads 2, 2 reads 0
    EXPECT_THROW(io::vrm_node_constraint_order(list, parent, "f"), InputError);
    list[1].source = 1;  // 2 reads 1, a child of 0, which reads 2: the source's ancestors count
    EXPECT_THROW(io::vrm_node_constraint_order(list, {-1, 0, -1}, "f"), InputError);
    list = {{K::Roll, 1, 1, {1, 0, 0}, 1.0}};  // its own source
    EXPECT_THROW(io::vrm_node_constraint_order(list, parent, "f"), InputError);
    // A chain of 5000 constraints, each reading the next: an error, not a stack overflow.
    list.clear();
    for (int i = 0; i < 5000; ++i) list.push_back({K::Rotation, i, i + 1, {1, 0, 0}, 1.0});
    EXPECT_THROW(io::vrm_node_constraint_order(list, std::vector<int>(5001, -1), "f"), InputError);
}

// Loading `avatar` with `clip` is one InputError whose message contains `expected`.
void expect_input_error(const std::string& avatar, const std::string& clip, const std::string& expected) {
    try {
        load_mesh(avatar, {.pose = {.animation = clip, .time = 0.5f}});
        ADD_FAILURE() << "no error for " << clip;
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
}

TEST_F(VrmFiles, BadInputIsOneInputError) {
    const std::string avatar = write_file("bad.vrm", rig_avatar(false).glb());
    const std::string good = rig_animation().glb();
    expect_input_error(avatar, dir_.file("inkshade-no-such-file.vrma"), "inkshade-no-such-file.vrma");
    expect_input_error(avatar, write_file("truncated.vrma", good.substr(0, good.size() / 2)), "truncated.vrma");
    expect_input_error(avatar, write_file("plain.vrma", textured_quad().glb()), "not a VRM animation");
    // NaN keyframes.
    GltfBuilder nan = one_bone_clip("spine", glm::dquat(1, 0, 0, 0));
    const float not_a_number = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(nan.bin.data() + nan.bin.size() - 4, &not_a_number, 4);
    expect_input_error(avatar, write_file("nan.vrma", nan.glb()), "nan.vrma");
    // A human bone on a node the .vrma does not have.
    GltfBuilder far = one_bone_clip("spine", glm::dquat(1, 0, 0, 0));
    far.doc["extensions"]["VRMC_vrm_animation"]["humanoid"]["humanBones"]["spine"]["node"] = 999;
    expect_input_error(avatar, write_file("far.vrma", far.glb()), "node 999");
    // An avatar without a humanoid, or one without its hips.
    const std::string clip = write_file("ok.vrma", good);
    expect_input_error(write_file("quad.glb", textured_quad().glb()), clip, "has no VRM humanoid");
    GltfBuilder hipless = rig_avatar(false);
    hipless.doc["extensions"]["VRMC_vrm"]["humanoid"]["humanBones"].erase("hips");
    expect_input_error(write_file("hipless.vrm", hipless.glb()), clip, "lacks required bones: hips");
}

}  // namespace
}  // namespace inkshade
