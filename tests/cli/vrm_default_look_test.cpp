// The plain command on a VRM draws it as three-vrm does: a file with MToon materials (VRM 1.0,
// VRM 0.x, or a glTF naming VRMC_materials_mtoon) takes the `vrm` style when no look is given,
// and that style is the mtoon model with the materials' own values, no ambient, no shadows,
// three.js's black background and a white directional light of intensity pi. Other files keep
// lambert; a named style or shading model still replaces the default.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/run_cli.hpp"
#include "io/avatar_files.hpp"

namespace inkshade::test {
namespace {

const std::string kView = " --size 96x96 --azimuth 20 --elevation 10 --samples 1 -o ";

std::string render(const std::string& model, const std::string& flags, const TempDir& dir, const std::string& name) {
    const std::string out = dir.file(name);
    const CliResult r = run_cli("render '" + model + "' " + flags + kView + "'" + out + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "") << name;
    return slurp(out);
}

TEST(VrmDefaultLook, FilesWithMtoonMaterialsTakeTheVrmStyle) {
    TempDir dir;
    for (AvatarFormat format : {AvatarFormat::Vrm1, AvatarFormat::Vrm0}) {
        const std::string what = format == AvatarFormat::Vrm1 ? "1.0" : "0.x";
        const std::string model = dir.write("avatar" + what + ".vrm", avatar(format).glb());
        const std::string plain = render(model, "", dir, "plain.png");
        EXPECT_EQ(plain, render(model, "--style vrm", dir, "vrm.png")) << what;
        EXPECT_NE(plain, render(model, "--style lambert", dir, "lambert.png")) << what;
        EXPECT_NE(plain, render(model, "--style mtoon", dir, "mtoon.png")) << what;  // a named style wins
    }
    // The extension alone does not decide: a .glb naming VRMC_materials_mtoon is an MToon file.
    const std::string glb = dir.write("avatar.glb", avatar(AvatarFormat::Vrm1).glb());
    EXPECT_EQ(render(glb, "", dir, "glb.png"), render(glb, "--style vrm", dir, "glb-vrm.png"));
}

TEST(VrmDefaultLook, OtherFilesKeepLambert) {
    TempDir dir;
    const std::string gltf = dir.write("avatar.glb", avatar(AvatarFormat::Gltf).glb());
    EXPECT_EQ(render(gltf, "", dir, "plain.png"), render(gltf, "--style lambert", dir, "lambert.png"));
    EXPECT_EQ(render("builtin:sphere", "", dir, "sphere.png"),
              render("builtin:sphere", "--style lambert", dir, "sphere-lambert.png"));
    // A .vrm that is not glTF at all: the loader's error, not a crash in the look's choice.
    const std::string junk = dir.write("junk.vrm", "not a glTF file");
    const CliResult r = run_cli("render '" + junk + "'" + kView + "'" + dir.file("x.png") + "'");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// The style is what docs/mtoon.md says, flag for flag: the mtoon model (threejs convention,
// the materials' own values) without shadows, lit by white at intensity pi, no ambient, black.
TEST(VrmDefaultLook, TheStyleIsMtoonWithoutAmbientOrShadows) {
    TempDir dir;
    const std::string model = dir.write("avatar.vrm", avatar(AvatarFormat::Vrm1).glb());
    EXPECT_EQ(render(model, "", dir, "plain.png"),
              render(model,
                     "--shading mtoon --set shadows=false --ambient 0,0,0 --background black --light-color 1,1,1 "
                     "--light-intensity 3.14159265",
                     dir, "flags.png"));
}

// A batch without a style takes each model's own, as `render` does: the VRM its `vrm` look, the
// plain glTF `lambert`, each in the folder of that style; a style given still wins.
TEST(VrmDefaultLook, BatchWithoutAStyleTakesEachModelsOwn) {
    TempDir dir;
    std::filesystem::create_directories(dir.file("models"));
    const std::string vrm = dir.write("models/avatar.vrm", avatar(AvatarFormat::Vrm1).glb());
    const std::string gltf = dir.write("models/plain.glb", avatar(AvatarFormat::Gltf).glb());
    const std::string flags = " --views 20:10 --size 96x96 --samples 1 --quiet -o '" + dir.file("out") + "'";
    const CliResult r = run_cli("batch --models '" + dir.file("models") + "'" + flags);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir.file("out/avatar/vrm/az020_el10.png")), render(vrm, "--style vrm", dir, "vrm.png"));
    EXPECT_EQ(slurp(dir.file("out/plain/lambert/az020_el10.png")), render(gltf, "", dir, "plain.png"));
    EXPECT_FALSE(std::filesystem::exists(dir.file("out/avatar/lambert")));
    const CliResult named = run_cli("batch --models '" + dir.file("models") + "' --styles toon" + flags);
    ASSERT_EQ(named.status, 0) << named.err;
    EXPECT_TRUE(std::filesystem::exists(dir.file("out/avatar/toon/az020_el10.png")));
    // An empty list given is still an error, in a manifest as on the command line.
    const std::string manifest = dir.write("jobs.jsonl", "{\"model\": \"" + vrm + "\", \"styles\": []}\n");
    const CliResult empty = run_cli("batch '" + manifest + "'" + flags);
    EXPECT_EQ(empty.status, 2);
    EXPECT_NE(empty.err.find("jobs.jsonl:1: styles: no style given"), std::string::npos) << empty.err;
    EXPECT_EQ(run_cli("batch --models '" + dir.file("models") + "' --styles ,"  + flags).status, 2);
}

}  // namespace
}  // namespace inkshade::test
