// Skinned glTF meshes: every vertex of the avatar's arm lands where linear blend skinning of the
// analytic joint matrices puts it (the file's own elbow pose), normals follow the blended
// matrix, weights are normalised as three.js does, and damaged skins are one-line errors.
#include <gtest/gtest.h>

#include <functional>

#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "io/avatar_files.hpp"
#include "io/gltf_skinning.hpp"
#include "support/expect_near.hpp"
#include "support/temp_dir.hpp"

namespace inkshade::test {
namespace {

using nlohmann::json;

glm::vec3 at(const std::vector<float>& xyz, size_t i) { return {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}; }

std::string load_error(const std::string& path, const LoadOptions& options = {}) {
    try {
        load_mesh(path, options);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(GltfSkinning, ArmVerticesAreTheLinearBlendOfTheJoints) {
    TempDir dir;
    const Mesh m = load_mesh(dir.write("avatar.glb", avatar(AvatarFormat::Gltf).glb()));
    const AvatarLayout l = avatar_layout();
    ASSERT_EQ(m.positions.size(), l.end);
    const AvatarPart arm = avatar_arm();
    size_t elbow_ring = 0;
    for (size_t i = 0; i < arm.positions.size() / 3; ++i) {
        SCOPED_TRACE(i);
        const glm::vec3 p = at(arm.positions, i);
        const glm::vec2 w = avatar_arm_weights(p.x);
        elbow_ring += w.x == 0.5f;
        expect_near(m.positions[l.arm + i], avatar_skinned(p, w, 0.0f));
        // The normal: the blended matrix's linear part times the bind normal, normalised.
        const glm::mat3 blend = w.x * glm::mat3(avatar_upper_arm(0)) + w.y * glm::mat3(avatar_lower_arm(0));
        expect_near(m.normals[l.arm + i], glm::normalize(blend * at(arm.normals, i)));
    }
    EXPECT_EQ(elbow_ring, 8u);  // the elbow's ring is half and half
    // The forearm is turned 30 degrees up about the elbow: its far end rises by 0.3 sin 30.
    const glm::vec3 tip = avatar_skinned({kArmEnd, kShoulder.y, 0}, {0, 1}, 0.0f);
    EXPECT_NEAR(tip.y - kElbow.y, 0.3f * std::sin(glm::radians(30.0f)), 1e-6f);
    // Unskinned parts are untouched: the body's first vertex is where the file has it.
    expect_near(m.positions[l.body], at(avatar_capsule({0, 0.35f, 0}, 0.75f, 0.2f).positions, 0));
}

TEST(GltfSkinning, WeightsAreNormalisedAsThreeJsDoes) {
    std::vector<float> w = {2, 2, 0, 0, 0, 0, 0, 0, 1, -1, 2, 0, 0.25f, 0.25f, 0, 0};
    io::normalize_skin_weights(w);
    EXPECT_EQ(std::vector<float>(w.begin(), w.begin() + 4), (std::vector<float>{0.5f, 0.5f, 0, 0}));
    EXPECT_EQ(std::vector<float>(w.begin() + 4, w.begin() + 8), (std::vector<float>{1, 0, 0, 0}));  // all zero
    EXPECT_EQ(std::vector<float>(w.begin() + 8, w.begin() + 12), (std::vector<float>{0.25f, -0.25f, 0.5f, 0}));
    EXPECT_EQ(std::vector<float>(w.begin() + 12, w.end()), (std::vector<float>{0.5f, 0.5f, 0, 0}));
}

// The avatar with its WEIGHTS_0 of the arm rewritten by `edit` (the accessor's floats).
std::string avatar_with_arm_weights(TempDir& dir, const std::function<void(std::vector<float>&)>& edit) {
    GltfBuilder g = avatar(AvatarFormat::Gltf);
    const int accessor = g.doc["meshes"][2]["primitives"][0]["attributes"]["WEIGHTS_0"];
    const int view = g.doc["accessors"][accessor]["bufferView"];
    const size_t offset = g.doc["bufferViews"][view]["byteOffset"], bytes = g.doc["bufferViews"][view]["byteLength"];
    std::vector<float> w(bytes / 4);
    std::memcpy(w.data(), g.bin.data() + offset, bytes);
    edit(w);
    std::memcpy(g.bin.data() + offset, w.data(), bytes);
    return dir.write("edited.glb", g.glb());
}

TEST(GltfSkinning, UnnormalisedWeightsPoseAsNormalisedOnes) {
    TempDir dir;
    const Mesh expected = load_mesh(dir.write("avatar.glb", avatar(AvatarFormat::Gltf).glb()));
    // Every arm weight doubled: the same pose. Weights all zero: the first joint (UpperArm) alone.
    const Mesh doubled = load_mesh(avatar_with_arm_weights(dir, [](std::vector<float>& w) {
        for (float& x : w) x *= 2.0f;
    }));
    const AvatarLayout l = avatar_layout();
    for (size_t i = l.arm; i < l.ball; ++i) expect_near(doubled.positions[i], expected.positions[i]);
    const Mesh zero =
        load_mesh(avatar_with_arm_weights(dir, [](std::vector<float>& w) { std::fill(w.begin(), w.end(), 0.0f); }));
    const AvatarPart arm = avatar_arm();
    for (size_t i = 0; i < arm.positions.size() / 3; ++i)
        expect_near(zero.positions[l.arm + i], avatar_skinned(at(arm.positions, i), {1, 0}, 0.0f));
}

TEST(GltfSkinning, DamagedSkinsAreOneLineErrors) {
    TempDir dir;
    struct Case {
        const char* name;
        std::function<void(GltfBuilder&)> edit;
        std::string message;
    };
    const std::vector<Case> cases =
        {
            {"joint index past the skin",
             [](GltfBuilder& g) {
        const int joints = g.doc["meshes"][2]["primitives"][0]["attributes"]["JOINTS_0"];
        const int view = g.doc["accessors"][joints]["bufferView"];
        g.bin[size_t(g.doc["bufferViews"][view]["byteOffset"])] = 7;  // vertex 0, weight 1
             },
             "JOINTS_0 of mesh 2 primitive 0 has joint 7 at vertex 0 but skin 0 has 2 joints"},
            {"joint node missing", [](GltfBuilder& g) { g.doc["skins"][0]["joints"][1] = 99; },
             "skin 0 joint 1 is node 99 but the file has 7 nodes"},
            {"inverse bind accessor missing", [](GltfBuilder& g) { g.doc["skins"][0]["inverseBindMatrices"] = 999; },
             "refers to accessor 999"},
            {"too few inverse bind matrices",
             [](GltfBuilder& g) {
        const int a = g.doc["skins"][0]["inverseBindMatrices"];
        g.doc["accessors"][a]["count"] = 1;
             },
             "inverseBindMatrices of skin 0 has 1 matrices for 2 joints"},
                            {"no JOINTS_0",
                             [](GltfBuilder& g) {
        g.doc["meshes"][2]["primitives"][0]["attributes"].erase("JOINTS_0");
                             },
                             "mesh 2 primitive 0 is skinned (node 3, skin 0) but has no JOINTS_0"},
        {"no WEIGHTS_0", [](GltfBuilder& g) { g.doc["meshes"][2]["primitives"][1]["attributes"].erase("WEIGHTS_0"); },
         "mesh 2 primitive 1 is skinned (node 3, skin 0) but has no WEIGHTS_0"},
        {"WEIGHTS_0 count",
         [](GltfBuilder& g) {
        const int a = g.doc["meshes"][2]["primitives"][0]["attributes"]["WEIGHTS_0"];
        g.doc["accessors"][a]["count"] = 3;
         },
         "WEIGHTS_0 of mesh 2 primitive 0 has 3 elements but POSITION has"},
        {"skin missing", [](GltfBuilder& g) { g.doc["nodes"][3]["skin"] = 4; },
         "node 3 refers to skin 4 but the file has 1"},
        };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        GltfBuilder g = avatar(AvatarFormat::Gltf);
        c.edit(g);
        const std::string path = dir.write("bad.glb", g.glb());
        const std::string error = load_error(path);
        EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
        EXPECT_NE(error.find(c.message), std::string::npos) << error;
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    }
}

}  // namespace
}  // namespace inkshade::test
