// VRM avatars (1.0 and 0.x, built by avatar_files.hpp) load with their MToon materials, their
// skinned pose and their expressions: an expression moves the bound morph targets by bind weight
// x expression weight, binary expressions round at 0.5, an override blocks blinking, VRM 0.x
// presets answer to their VRM 1.0 names and 0..100 bind weights scale to 0..1, as three-vrm.
#include <gtest/gtest.h>

#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "io/avatar_files.hpp"
#include "support/expect_near.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

glm::vec3 at(const std::vector<float>& xyz, size_t i) { return {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}; }

void expect_head(const Mesh& m, float happy, float blink) {
    const AvatarLayout l = avatar_layout();
    const AvatarPart head = avatar_sphere(glm::vec3(0), kHeadRadius, 12, 16);
    for (size_t i = 0; i < head.positions.size() / 3; ++i) {
        const glm::vec3 p = at(head.positions, i);
        expect_near(m.positions[l.head + i], kHeadCentre + p + happy * avatar_happy(p) + blink * avatar_blink(p));
    }
}

Mesh with_expressions(const std::string& path, std::vector<NamedWeight> expressions,
                      std::vector<NamedWeight> morphs = {}) {
    LoadOptions o;
    o.pose.expressions = std::move(expressions);
    o.pose.morphs = std::move(morphs);
    return load_mesh(path, o);
}

std::string load_error(const std::string& path, std::vector<NamedWeight> expressions) {
    try {
        with_expressions(path, std::move(expressions));
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

class VrmAvatar : public testing::TestWithParam<AvatarFormat> {};

TEST_P(VrmAvatar, LoadsWithMaterialsSkinnedPoseAndExpressions) {
    TempDir dir;
    const std::string path = dir.write("avatar.vrm", avatar(GetParam()).glb());
    const Mesh rest = load_mesh(path);
    ASSERT_EQ(rest.materials.size(), 3u);
    EXPECT_FALSE(rest.materials[0].mtoon.empty());  // skin
    EXPECT_FALSE(rest.materials[1].mtoon.empty());  // cloth
    EXPECT_TRUE(rest.materials[2].unlit);           // the red ball
    EXPECT_TRUE(rest.warnings.empty()) << rest.warnings.front();
    // The file's pose: the forearm turned 30 degrees at the elbow by linear blend skinning.
    const AvatarLayout l = avatar_layout();
    const glm::vec3 p = at(avatar_arm().positions, 8 * 4);  // the first vertex of the hand's ring
    expect_near(rest.positions[l.arm + 8 * 4], avatar_skinned(p, {0, 1}, 0.0f));
    expect_head(rest, 0, 0);

    expect_head(with_expressions(path, {{"happy", 1}}), 1, 0);
    expect_head(with_expressions(path, {{"happy", 0.4f}}), 0.4f, 0);
    expect_head(with_expressions(path, {{"smirk", 1}}), 0.5f, 0);                   // bound at half weight
    expect_head(with_expressions(path, {{"happy", 0.5f}, {"smirk", 1}}), 1.0f, 0);  // binds add up
    // Binary: 0.5 is off, above it fully on.
    expect_head(with_expressions(path, {{"blink", 0.5f}}), 0, 0);
    expect_head(with_expressions(path, {{"blink", 0.51f}}), 0, 1);
    // Expressions win over the file's weights of the targets they bind, and weights by name
    // come last.
    expect_head(with_expressions(path, {{"blink", 1}}, {{"happy", 0.3f}}), 0.3f, 1);
}

TEST_P(VrmAvatar, UnknownExpressionIsAOneLineError) {
    TempDir dir;
    const std::string path = dir.write("avatar.vrm", avatar(GetParam()).glb());
    EXPECT_EQ(load_error(path, {{"hapy", 1}}),
              path + ": no expression 'hapy' (did you mean 'happy'?); its expressions: " +
                  (GetParam() == AvatarFormat::Vrm1 ? "'blink', 'happy', 'smirk'"     // VRM 1.0: by name
                                                    : "'happy', 'blink', 'Smirk'"));  // VRM 0.x: in file order
}

INSTANTIATE_TEST_SUITE_P(Formats, VrmAvatar, testing::Values(AvatarFormat::Vrm1, AvatarFormat::Vrm0),
                         [](const auto& p) { return p.param == AvatarFormat::Vrm1 ? "Vrm1" : "Vrm0"; });

TEST(VrmExpressions, HappyBlocksBlinkInVrmOne) {
    TempDir dir;
    const std::string path = dir.write("avatar.vrm", avatar(AvatarFormat::Vrm1).glb());
    expect_head(with_expressions(path, {{"blink", 1}, {"happy", 1}}), 1, 0);  // overrideBlink: block
    expect_head(with_expressions(path, {{"blink", 1}, {"happy", 0}}), 0, 1);
    // VRM 0.x has no overrides: both apply.
    const std::string v0 = dir.write("avatar0.vrm", avatar(AvatarFormat::Vrm0).glb());
    expect_head(with_expressions(v0, {{"blink", 1}, {"happy", 1}}), 1, 1);
}

TEST(VrmExpressions, BindsToMissingTargetsAreLeftOutWithAWarning) {
    TempDir dir;
    GltfBuilder g = avatar(AvatarFormat::Vrm1);
    g.doc["extensions"]["VRMC_vrm"]["expressions"]["preset"]["happy"]["morphTargetBinds"].push_back(
        {{"node", 2}, {"index", 9}, {"weight", 1.0}});
    g.doc["extensions"]["VRMC_vrm"]["expressions"]["preset"]["sad"] = {
        {"morphTargetBinds", {{{"node", 1}, {"index", 0}, {"weight", 1.0}}}}};  // the body has no targets
    const std::string path = dir.write("avatar.vrm", g.glb());
    const Mesh m = with_expressions(path, {{"happy", 1}, {"sad", 1}});
    expect_head(m, 1, 0);
    ASSERT_EQ(m.warnings.size(), 2u);
    EXPECT_EQ(m.warnings[0],
              path + ": expression 'happy' binds morph target 9 of node 2, whose mesh has 2; bind left out");
    EXPECT_EQ(m.warnings[1],
              path + ": expression 'sad' binds morph target 0 of node 1, whose mesh has 0; bind left out");
}

TEST(VrmExpressions, FilesWithoutExpressions) {
    TempDir dir;
    const std::string path = dir.write("avatar.glb", avatar(AvatarFormat::Gltf).glb());
    EXPECT_EQ(load_error(path, {{"happy", 1}}), path + ": no expression 'happy': the file has no VRM expressions");
}

}  // namespace
}  // namespace inkshade::test
