// VRM spring bones read from files (VRMC_springBone 1.0 and VRM 0.x secondaryAnimation): a chain
// swings under gravity in the loaded pose, is left in the file's pose with spring bones off, a
// VRM 0.x bone group moves as the same VRMC_springBone spring does (its collider's z mirrored,
// as three-vrm reads it), and bad declarations are one-line InputErrors.
#include <gtest/gtest.h>

#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "io/gltf_files.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

// A quad on node 0 with a chain below it: nodes 1 (at the origin), 2 and 3, 0.3 apart along +x.
GltfBuilder chain() {
    GltfBuilder g = textured_quad();
    g.doc["nodes"] = nlohmann::json::array();
    g.node({{"mesh", 0}, {"children", {1}}});
    g.node({{"children", {2}}});
    g.node({{"translation", {0.3, 0, 0}}, {"children", {3}}});
    g.node({{"translation", {0.3, 0, 0}}});
    g.scene({0});
    return g;
}

nlohmann::json joint(int node) {
    return {{"node", node}, {"stiffness", 0.2}, {"gravityPower", 1.0}, {"dragForce", 0.4}, {"hitRadius", 0.02}};
}

// VRMC_springBone: one spring 1-2-3 with a sphere collider at `offset` on node 0.
GltfBuilder v1(nlohmann::json offset = {0.06, -0.32, -0.06}) {
    GltfBuilder g = chain();
    g.doc["extensionsUsed"] = {"VRMC_springBone"};
    g.doc["extensions"]["VRMC_springBone"] = {
        {"specVersion", "1.0"},
        {"colliders", {{{"node", 0}, {"shape", {{"sphere", {{"offset", offset}, {"radius", 0.1}}}}}}}},
        {"colliderGroups", {{{"colliders", {0}}}}},
        {"springs", {{{"joints", {joint(1), joint(2), joint(3)}}, {"colliderGroups", {0}}}}}};
    return g;
}

// VRM 0.x: a bone group rooted at node 1 (so nodes 1, 2 and 3 are joints) with the same values.
GltfBuilder v0(nlohmann::json offset) {
    GltfBuilder g = chain();
    g.doc["extensionsUsed"] = {"VRM"};
    g.doc["extensions"]["VRM"]["secondaryAnimation"] = {
        {"colliderGroups", {{{"node", 0}, {"colliders", {{{"offset", offset}, {"radius", 0.1}}}}}}},
        {"boneGroups",
         {{{"stiffiness", 0.2},
           {"gravityPower", 1.0},
           {"dragForce", 0.4},
           {"hitRadius", 0.02},
           {"center", -1},
           {"bones", {1}},
           {"colliderGroups", {0}}}}}};
    return g;
}

std::vector<PosedNode> nodes_at(const std::string& path, float time, bool springs = true) {
    Pose pose;
    pose.time = time;
    pose.spring_bones = springs;
    return posed_nodes(path, pose);
}

std::string error_of(const GltfBuilder& g, float time = 1.0f) {
    TempDir dir;
    try {
        nodes_at(dir.write("bad.glb", g.glb()), time);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

TEST(VrmSpringBones, AChainFallsUnderGravityAndStaysPutWhenOff) {
    TempDir dir;
    const std::string path = dir.write("chain.glb", v1().glb());
    const std::vector<PosedNode> rest = nodes_at(path, 0.0f), fallen = nodes_at(path, 2.0f),
                                 off = nodes_at(path, 2.0f, false);
    ASSERT_EQ(fallen.size(), 4u);
    EXPECT_LT(fallen[3].position.y, rest[3].position.y - 0.1);
    EXPECT_NEAR(glm::length(fallen[2].position - fallen[1].position), 0.3, 1e-9);  // bones keep their length
    EXPECT_NEAR(glm::length(fallen[3].position - fallen[2].position), 0.3, 1e-9);
    for (size_t i = 0; i < off.size(); ++i) EXPECT_EQ(off[i].position, rest[i].position) << i;
}

TEST(VrmSpringBones, AVrm0BoneGroupMovesAsTheSameSpringWithItsColliderZMirrored) {
    TempDir dir;
    const std::vector<PosedNode> one = nodes_at(dir.write("v1.glb", v1({0.06, -0.32, -0.06}).glb()), 1.0f);
    const std::vector<PosedNode> zero =
        nodes_at(dir.write("v0.glb", v0({{"x", 0.06}, {"y", -0.32}, {"z", 0.06}}).glb()), 1.0f);
    const std::vector<PosedNode> unmirrored = nodes_at(dir.write("v1z.glb", v1({0.06, -0.32, 0.06}).glb()), 1.0f);
    for (size_t i = 0; i < one.size(); ++i)
        EXPECT_NEAR(glm::length(one[i].position - zero[i].position), 0.0, 1e-12) << i;
    EXPECT_GT(glm::length(unmirrored[3].position - one[3].position), 1e-3);  // the collider matters
}

TEST(VrmSpringBones, BadDeclarationsAreInputErrors) {
    auto spring = [](auto edit) {
        GltfBuilder g = v1();
        edit(g.doc["extensions"]["VRMC_springBone"]);
        return error_of(g);
    };
    EXPECT_NE(spring([](auto& e) {
                  e["springs"][0]["joints"][1]["node"] = 9;
              }).find("VRMC_springBone.springs[0].joints[1].node is 9 but the file has 4 nodes"),
              std::string::npos);
    EXPECT_NE(spring([](auto& e) {
                  e["colliders"][0]["shape"]["sphere"]["radius"] = -1;
              }).find("VRMC_springBone.colliders[0].shape.radius is -1, outside [0, inf)"),
              std::string::npos);
    EXPECT_NE(spring([](auto& e) {
                  e["springs"][0]["joints"][0]["stiffness"] = "stiff";
              }).find("VRMC_springBone.springs[0].joints[0].stiffness is not a finite number"),
              std::string::npos);
    EXPECT_NE(
        spring([](auto& e) { e["springs"][0]["joints"][0]["dragForce"] = 2; }).find("dragForce is 2, outside [0, 1]"),
        std::string::npos);
    EXPECT_NE(spring([](auto& e) {
                  e["springs"][0]["joints"][0]["gravityDir"] = {0, 1};
              }).find("gravityDir is not 3 numbers"),
              std::string::npos);
    EXPECT_NE(spring([](auto& e) {
                  e["springs"][0]["colliderGroups"] = {3};
              }).find("colliderGroups[0] is 3 but the file has 1 collider groups"),
              std::string::npos);
    EXPECT_NE(spring([](auto& e) { e["colliderGroups"][0]["colliders"] = {1}; }).find("but the file has 1 colliders"),
              std::string::npos);
}

TEST(VrmSpringBones, CyclesAndTooMuchWorkAreInputErrors) {
    GltfBuilder cycle = v1();
    cycle.doc["nodes"][3]["children"] = {2};  // 2 -> 3 -> 2
    cycle.doc["nodes"][1]["children"] = nlohmann::json::array();
    EXPECT_NE(error_of(cycle).find("lies in a cycle of the node hierarchy"), std::string::npos) << error_of(cycle);
    GltfBuilder v0_cycle = v0({{"z", 0}});
    v0_cycle.doc["nodes"][3]["children"] = {2};
    EXPECT_NE(error_of(v0_cycle).find("more than 10000 spring bone joints"), std::string::npos);
    EXPECT_NE(error_of(v1(), 1e7f).find("turn spring bones off"), std::string::npos) << error_of(v1(), 1e7f);
}

TEST(VrmSpringBones, TheFileTellsHowManyJoints) {
    TempDir dir;
    EXPECT_EQ(load_mesh(dir.write("v1.glb", v1().glb())).pose_names.spring_joints, 2u);
    EXPECT_EQ(load_mesh(dir.write("v0.glb", v0({{"z", 0}}).glb())).pose_names.spring_joints, 3u);
}

}  // namespace
}  // namespace inkshade::test
