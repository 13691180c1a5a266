// --time, --animation, --morph and --expression on the command line: render, lines and view
// take them, and a bad value or a name the file does not have is exit 2 with one line naming
// the option or the file, with the file's names and a did-you-mean.
#include <gtest/gtest.h>

#include "cli/run_cli.hpp"
#include "io/avatar_files.hpp"

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

TEST(PosingCli, HelpListsThePoseOptions) {
    for (const char* command : {"render", "lines", "view"}) {
        const CliResult r = run_cli(std::string(command) + " --help");
        for (const char* option : {"--time", "--animation", "--morph", "--expression"})
            EXPECT_NE(r.out.find(option), std::string::npos) << command << " " << option;
    }
}

}  // namespace
}  // namespace inkshade::test
