// Morph targets: the file's default weights (mesh.weights, then node.weights) and weights by
// name (mesh.extras.targetNames) displace the head's vertices by exactly weight x target, and an
// unknown name is a one-line error listing the names.
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
    size_t moved = 0;
    for (size_t i = 0; i < head.positions.size() / 3; ++i) {
        const glm::vec3 p = at(head.positions, i);
        const glm::vec3 offset = happy * avatar_happy(p) + blink * avatar_blink(p);
        moved += glm::length(offset) > 1e-3f;
        expect_near(m.positions[l.head + i], kHeadCentre + p + offset);
    }
    if (happy != 0.0f || blink != 0.0f) {
        EXPECT_GT(moved, 10u);
    }
}

LoadOptions morphs(std::vector<NamedWeight> weights) {
    LoadOptions o;
    o.pose.morphs = std::move(weights);
    return o;
}

TEST(GltfMorphTargets, MeshWeightsThenNodeWeightsAreTheDefault) {
    TempDir dir;
    GltfBuilder g = avatar(AvatarFormat::Gltf);
    expect_head(load_mesh(dir.write("rest.glb", g.glb())), 0, 0);
    g.doc["meshes"][1]["weights"] = {0.5, 0.0};
    expect_head(load_mesh(dir.write("mesh.glb", g.glb())), 0.5f, 0);
    g.doc["nodes"][2]["weights"] = {0.25, 1.0};  // the node's weights replace the mesh's
    expect_head(load_mesh(dir.write("node.glb", g.glb())), 0.25f, 1.0f);
}

TEST(GltfMorphTargets, WeightsByNameReplaceTheDefaults) {
    TempDir dir;
    GltfBuilder g = avatar(AvatarFormat::Gltf);
    g.doc["meshes"][1]["weights"] = {0.5, 0.5};
    const std::string path = dir.write("avatar.glb", g.glb());
    expect_head(load_mesh(path, morphs({{"happy", 1.0f}})), 1.0f, 0.5f);
    expect_head(load_mesh(path, morphs({{"blink", 0.0f}, {"Happy", -0.5f}})), -0.5f, 0.0f);
    expect_head(load_mesh(path, morphs({{"blink", 1.0f}, {"blink", 0.2f}})), 0.5f, 0.2f);  // the last wins
}

TEST(GltfMorphTargets, UnknownNamesAreOneLineErrors) {
    TempDir dir;
    const std::string path = dir.write("avatar.glb", avatar(AvatarFormat::Gltf).glb());
    auto error = [](const std::string& file, const LoadOptions& o) -> std::string {
        try {
            load_mesh(file, o);
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_EQ(error(path, morphs({{"hapy", 1}})),
              path + ": no morph target 'hapy' (did you mean 'happy'?); its morph targets: 'happy', 'blink'");
    GltfBuilder unnamed = avatar(AvatarFormat::Gltf);
    unnamed.doc["meshes"][1].erase("extras");
    const std::string plain = dir.write("unnamed.glb", unnamed.glb());
    EXPECT_EQ(error(plain, morphs({{"happy", 1}})),
              plain + ": no morph target 'happy': the file has no named morph targets (mesh.extras.targetNames)");
    EXPECT_EQ(error("builtin:sphere", morphs({{"happy", 1}})),
              "builtin:sphere: only glTF, GLB and VRM files have animations, morph targets and expressions");
}

TEST(GltfMorphTargets, TargetOfAnotherLengthIsAnError) {
    TempDir dir;
    GltfBuilder g = avatar(AvatarFormat::Gltf);
    const int happy = g.doc["meshes"][1]["primitives"][0]["targets"][0]["POSITION"];
    g.doc["accessors"][happy]["count"] = 5;
    const std::string path = dir.write("avatar.glb", g.glb());
    try {
        load_mesh(path, morphs({{"happy", 1}}));
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path + ": POSITION of morph target 0 of mesh 1 primitive 0 has 5 elements but POSITION has " +
                      std::to_string(avatar_sphere(glm::vec3(0), kHeadRadius, 12, 16).positions.size() / 3));
    }
    EXPECT_NO_THROW(load_mesh(path));  // weight 0: the target is never read
}

}  // namespace
}  // namespace inkshade::test
