// The `inkshade view --script` format (scene/view_script.hpp), read without a window: each
// command's fields, comments, line endings, the one-line errors, and the fuzz target's seeds and
// saved inputs (tests/scene/fuzz_regressions/view_script/) replayed through fuzz/view_script_target.hpp.
#include <gtest/gtest.h>

#include <string>

#include "../../fuzz/view_script_target.hpp"
#include "inkshade/error.hpp"
#include "support/fuzz_replay.hpp"
#include "support/temp_dir.hpp"

namespace inkshade {
namespace {

std::string error_of(std::string_view text) {
    try {
        parse_script(text, "s.txt");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(ViewScript, EveryCommandParsesToItsFields) {
    const auto c = parse_script(
        "frames 12\nkey f\nkey 3\nset outline.color=#ff8800\nstyle cel-002\nlight-pos 1, 2.5 ,-3\n"
        "orbit 30 -15\nzoom 0.5\nopen my model.obj\nscreenshot a.png\nsave-frame f.png\nsave-style s.toml\n"
        "gui off\nquit\n",
        "s.txt");
    ASSERT_EQ(c.size(), 14u);
    EXPECT_EQ(c[0].kind, ScriptCommand::Frames);
    EXPECT_EQ(c[0].count, 12);
    EXPECT_EQ(c[1].kind, ScriptCommand::Key);
    EXPECT_EQ(c[1].count, 'F');  // GLFW's key code: upper case
    EXPECT_EQ(c[2].count, '3');
    EXPECT_EQ(c[3].kind, ScriptCommand::Set);
    EXPECT_EQ(c[3].argument, "outline.color=#ff8800");  // '#' after no blank is not a comment
    EXPECT_EQ(c[4].kind, ScriptCommand::StyleName);
    EXPECT_EQ(c[4].argument, "cel-002");
    EXPECT_EQ(c[5].kind, ScriptCommand::LightPos);
    EXPECT_EQ(c[5].vector, glm::vec3(1.0f, 2.5f, -3.0f));
    EXPECT_EQ(c[6].kind, ScriptCommand::Orbit);
    EXPECT_EQ(c[6].vector, glm::vec3(30.0f, -15.0f, 0.0f));
    EXPECT_EQ(c[7].kind, ScriptCommand::Zoom);
    EXPECT_EQ(c[7].vector.x, 0.5f);
    EXPECT_EQ(c[8].kind, ScriptCommand::Open);
    EXPECT_EQ(c[8].argument, "my model.obj");  // paths keep their blanks
    EXPECT_EQ(c[9].kind, ScriptCommand::Screenshot);
    EXPECT_EQ(c[10].kind, ScriptCommand::SaveFrame);
    EXPECT_EQ(c[11].kind, ScriptCommand::SaveStyle);
    EXPECT_EQ(c[12].kind, ScriptCommand::Gui);
    EXPECT_EQ(c[12].count, 0);
    EXPECT_EQ(c[13].kind, ScriptCommand::Quit);
    for (size_t i = 0; i < c.size(); ++i) EXPECT_EQ(c[i].line, int(i) + 1);
}

TEST(ViewScript, CommentsBlankLinesAndCrlfAreSkippedAndLinesCounted) {
    const auto c = parse_script("# header\r\n\r\n\t frames 1 # one frame\r\n   \nscreenshot a.png\r\n", "s.txt");
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0].line, 3);
    EXPECT_EQ(c[0].count, 1);
    EXPECT_EQ(c[1].line, 5);
    EXPECT_EQ(c[1].argument, "a.png");  // the \r is not part of the path
}

TEST(ViewScript, ErrorsAreOneLineWithSourceAndLine) {
    EXPECT_EQ(error_of("frames 1\nfly-away now\n"),
              "s.txt:2: unknown command 'fly-away' (frames, key, set, style, light-pos, orbit, zoom, open, "
              "screenshot, save-frame, save-style, gui, quit)");
    EXPECT_EQ(error_of("frames -1"), "s.txt:1: frames: expected a count 0..1000000");
    EXPECT_EQ(error_of("frames 2.5"), "s.txt:1: frames: expected a count 0..1000000");
    EXPECT_EQ(error_of("zoom 0"), "s.txt:1: zoom: the factor must be positive");
    EXPECT_EQ(error_of("orbit 1e39 0"), "s.txt:1: '1e39' is not a number");
    EXPECT_EQ(error_of("light-pos 1,2"), "s.txt:1: expected light-pos X,Y,Z");
    EXPECT_EQ(error_of("key FF"), "s.txt:1: key: expected one letter or digit, got 'FF'");
    EXPECT_EQ(error_of("gui maybe"), "s.txt:1: gui: expected on or off");
    EXPECT_EQ(error_of("set levels"), "s.txt:1: expected set NAME=VALUE");
    EXPECT_EQ(error_of("open"), "s.txt:1: open: expected a name or path");
    // Control characters in a quoted token print as '?': the message stays one printable line.
    EXPECT_EQ(error_of("fr\x1b[2Jme\x01 1"),
              "s.txt:1: unknown command 'fr?[2Jme?' (frames, key, set, style, light-pos, orbit, zoom, open, "
              "screenshot, save-frame, save-style, gui, quit)");
}

TEST(ViewScript, LongerThanTheLimitIsAnErrorNotAnAllocation) {
    std::string text;
    for (size_t i = 0; i <= kMaxScriptCommands; ++i) text += "quit\n";
    EXPECT_EQ(error_of(text), "s.txt: script longer than 100000 commands");
    text.resize(text.size() - 5);
    EXPECT_EQ(parse_script(text, "s.txt").size(), kMaxScriptCommands);
}

TEST(ViewScript, ReadScriptNamesAMissingFile) {
    test::TempDir dir;
    const std::string missing = (dir.path() / "none.txt").string();
    try {
        read_script(missing);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), missing + ": cannot open script");
    }
    EXPECT_EQ(read_script(dir.write("s.txt", "frames 3\n")).at(0).count, 3);
}

TEST(ViewScriptFuzzRegressions, ReplaySeedsAndSavedInputs) {
    test::replay_fuzz_inputs({"fuzz/corpus/view_script", "tests/scene/fuzz_regressions/view_script"},
                             [](const std::string& bytes) { fuzz::view_script_input(bytes); });
}

// The harness itself: a broken promise is reported, not swallowed.
TEST(ViewScriptFuzzRegressions, HarnessReportsACommandOutOfOrder) {
    ScriptCommand c;
    c.kind = ScriptCommand::Frames;
    c.line = 2;
    EXPECT_NO_THROW(fuzz::check_script_command(c, 1));
    EXPECT_THROW(fuzz::check_script_command(c, 2), fuzz::ContractBroken);
    c.count = 2000000;
    EXPECT_THROW(fuzz::check_script_command(c, 1), fuzz::ContractBroken);
}

}  // namespace
}  // namespace inkshade
