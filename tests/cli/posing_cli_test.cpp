// --time, --animation, --morph and --expression on the command line: render, lines and view
// take them, and a bad value or a name the file does not have is exit 2 with one line naming
// the option or the file, with the file's names and a did-you-mean.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "io/avatar_files.hpp"
#include "io/vrm_rig_files.hpp"

namespace inkshade::test {
namespace {

void expect_one_line_error(const std::string& args, const std::string& message) {
    SCOPED_TRACE(args);
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
}

TEST(PosingCli, BadPosesAreOneLineErrors) {
    TempDir dir;
    const std::string path = dir.write("avatar.vrm", avatar(AvatarFormat::Vrm1).glb());
    const std::string out = " -o " + dir.file("out.png");
    expect_one_line_error("render " + path + " --animation wav" + out,
                          path + ": no animation 'wav' (did you mean 'wave'?); its animations: 0 'wave', 1 'hop'");
    expect_one_line_error("lines " + path + " --animation 7 -o " + dir.file("x.svg"), "no animation '7'");
    expect_one_line_error("render " + path + " --morph happy" + out, "--morph: expected NAME=WEIGHT, got 'happy'");
    expect_one_line_error("render " + path + " --morph happy=x" + out, "--morph: expected NAME=WEIGHT, got 'happy=x'");
    expect_one_line_error("render " + path + " --morph hapy=1" + out,
                          "no morph target 'hapy' (did you mean 'happy'?); its morph targets: 'happy', 'blink'");
    expect_one_line_error("render " + path + " --morph happy=1e30" + out,
                          "--morph: happy: morph weights are in [-1000, 1000], got 1e+30");
    expect_one_line_error("render " + path + " --expression happy=2" + out,
                          "--expression: happy: expression weights are in [0, 1], got 2");
    expect_one_line_error("render " + path + " --expression sorrow=1" + out,
                          "no expression 'sorrow'; its expressions: 'blink', 'happy', 'smirk'");
    expect_one_line_error(
        "render builtin:sphere --animation wave" + out,
        "builtin:sphere: only glTF, GLB and VRM files have animations, morph targets and expressions");
    expect_one_line_error("render " + path + " --time" + out, "--time");
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.png")));
}

// --animation FILE.vrma: a VRM animation file, relative to the working directory; a missing or
// bad one is exit 2 with one line naming it.
TEST(PosingCli, VrmAnimationFiles) {
    TempDir dir;
    const std::string avatar = dir.write("rig.vrm", rig_avatar(false).glb());
    const std::string clip = dir.write("clip.vrma", rig_animation().glb());
    const std::string common = " --lines border --size 64x64 -o ";
    auto r = run_cli("lines " + avatar + " --animation " + clip + " --time 0.3" + common + dir.file("a.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli("lines " + avatar + common + dir.file("rest.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir.file("a.svg")), slurp(dir.file("rest.svg")));
    expect_one_line_error("lines " + avatar + " --animation " + dir.file("none.vrma") + common + dir.file("b.svg"),
                          dir.file("none.vrma"));
    const std::string quad = dir.write("quad.vrma", textured_quad().glb());
    expect_one_line_error("lines " + avatar + " --animation " + quad + common + dir.file("b.svg"),
                          quad + ": is not a VRM animation");
}

TEST(PosingCli, LinesFollowThePose) {
    TempDir dir;
    const std::string path = dir.write("avatar.glb", avatar(AvatarFormat::Gltf).glb());
    const std::string common = " --lines contour --size 160x160 --azimuth 0 --elevation 0 --ortho -o ";
    auto r = run_cli("lines " + path + common + dir.file("rest.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli("lines " + path + " --animation wave --time 2" + common + dir.file("up.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli("lines " + path + " --animation 0 --time 9" + common + dir.file("clamped.svg"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(slurp(dir.file("rest.svg")), slurp(dir.file("up.svg")));
    EXPECT_EQ(slurp(dir.file("up.svg")), slurp(dir.file("clamped.svg")));  // 9 s is past the end: the last key
}

// The lines of `info`'s output from the one starting with `first` to the end, minus the load time.
std::string info_tail(const std::string& out, const std::string& first) {
    const size_t at = out.find("\n" + first);
    if (at == std::string::npos) return "(no line '" + first + "' in:\n" + out + ")";
    const std::string tail = out.substr(at + 1);
    return tail.substr(0, tail.find("load time:"));
}

TEST(PosingCli, InfoListsWhatThePoseOptionsTake) {
    TempDir dir;
    const std::string vrm1 = dir.write("avatar.vrm", avatar(AvatarFormat::Vrm1).glb());
    auto r = run_cli("info " + vrm1);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(info_tail(r.out, "animations:"),
              "animations:           2\n"
              "  0 'wave': 2 s\n"
              "  1 'hop': 2 s\n"
              "morph targets:        2\n"
              "  'happy'\n"
              "  'blink'\n"
              "expressions:          3\n"
              "  'blink' (preset)\n"
              "  'happy' (preset)\n"
              "  'smirk' (custom)\n");
    // VRM 0.x presets by the VRM 1.0 names --expression takes (joy -> happy), custom groups by name.
    r = run_cli("info " + dir.write("avatar0.vrm", avatar(AvatarFormat::Vrm0).glb()));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(info_tail(r.out, "expressions:"),
              "expressions:          3\n"
              "  'happy' (preset)\n"
              "  'blink' (preset)\n"
              "  'Smirk' (custom)\n");
    // Plain glTF: no expressions line; a file without any of them: none of the three lines.
    r = run_cli("info " + dir.write("avatar.glb", avatar(AvatarFormat::Gltf).glb()));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(info_tail(r.out, "morph targets:"), "morph targets:        2\n  'happy'\n  'blink'\n");
    r = run_cli("info builtin:sphere");
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* kind : {"animations:", "morph targets:", "expressions:"})
        EXPECT_EQ(r.out.find(kind), std::string::npos) << kind;
}

TEST(PosingCli, InfoGivesNoDurationForUnreadableKeyframes) {
    TempDir dir;
    GltfBuilder g = avatar(AvatarFormat::Gltf);
    g.doc["animations"][1]["samplers"][0]["input"] = 999;  // no such accessor
    auto r = run_cli("info " + dir.write("broken.glb", g.glb()));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("\n  0 'wave': 2 s\n  1 'hop': duration unknown (its keyframe times cannot be read)\n"),
              std::string::npos)
        << r.out;
    r = run_cli("render " + dir.file("broken.glb") + " --animation hop -o " + dir.file("x.png"));
    EXPECT_EQ(r.status, 2);  // posing by it says what is wrong
    EXPECT_EQ(line_count(r.err), 1) << r.err;
}

TEST(PosingCli, HelpListsThePoseOptions) {
    for (const char* command : {"render", "lines", "view"}) {
        const CliResult r = run_cli(std::string(command) + " --help");
        for (const char* option : {"--time", "--animation", "--morph", "--expression"})
            EXPECT_NE(r.out.find(option), std::string::npos) << command << " " << option;
    }
}

}  // namespace
}  // namespace inkshade::test
