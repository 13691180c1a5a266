// `inkshade view` under Xvfb (xvfb-run from the xvfb package, installed by scripts/setup) with
// Mesa llvmpipe: the window shows what `inkshade render` writes, keys and script commands
// change it as the CLI options do, and bad input keeps the viewer alive.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

constexpr const char* kXvfb = "xvfb-run -a -s '-screen 0 640x480x24'";

CliResult run_view(const std::string& args) { return run_cli("view " + args, kXvfb); }

// Fraction of pixels whose RGB channels all lie within `tolerance` of the other image's.
double matching_fraction(const Image& a, const Image& b, int tolerance = 2) {
    if (a.width != b.width || a.height != b.height) return 0.0;
    size_t same = 0, n = size_t(a.width) * size_t(a.height);
    for (size_t i = 0; i < n; ++i) {
        bool ok = true;
        for (int c = 0; c < 3; ++c) ok &= std::abs(int(a.rgba[i * 4 + c]) - int(b.rgba[i * 4 + c])) <= tolerance;
        same += ok;
    }
    return double(same) / double(n);
}

double matches_render(const std::string& shot, const std::string& render_args, const TempDir& dir) {
    const std::string ref = dir.file("ref.png");
    CliResult r = run_cli("render " + render_args + " -o " + ref);
    EXPECT_EQ(r.status, 0) << r.err;
    return matching_fraction(read_png(shot), read_png(ref));
}

std::string script(const TempDir& dir, const std::string& text) { return dir.write("script.txt", text); }

TEST(ViewCommand, ScreenshotEqualsRenderOfSameStyleAndCamera) {
    TempDir dir;
    const std::string shot = dir.file("shot.png");
    CliResult r = run_view("builtin:torus --style cel-000 --size 160x120 --hide-gui --frames 3 --screenshot " + shot);
    ASSERT_EQ(r.status, 0) << r.err;
    const Image image = read_png(shot);
    ASSERT_EQ(image.width, 160);
    ASSERT_EQ(image.height, 120);
    // Not blank: the torus covers part of the window, the background the rest.
    int background = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4) background += image.rgba[i] == 255 && image.rgba[i + 1] == 255;
    EXPECT_GT(background, 1000);
    EXPECT_LT(background, 160 * 120 - 1000);
    EXPECT_GE(matches_render(shot, "builtin:torus --style cel-000 --size 160x120", dir), 0.99);
}

TEST(ViewCommand, KeyFCyclesShadingModelsLikeRender) {
    TempDir dir;
    const std::string a = dir.file("a.png"), b = dir.file("b.png");
    CliResult r =
        run_view("builtin:sphere --shading gooch --size 96x96 --script " +
                 script(dir, "gui off\nframes 1\nscreenshot " + a + "\nkey F\nframes 1\nscreenshot " + b + "\n"));
    ASSERT_EQ(r.status, 0) << r.err;
    // The viewer names the model F switched to; the second screenshot is that model's render.
    const std::string tag = "shading model ";
    size_t at = r.err.find(tag);
    ASSERT_NE(at, std::string::npos) << r.err;
    const std::string next = r.err.substr(at + tag.size(), r.err.find('\n', at) - at - tag.size());
    EXPECT_NE(next, "gooch");
    EXPECT_LT(matching_fraction(read_png(a), read_png(b)), 0.9);
    EXPECT_GE(matches_render(a, "builtin:sphere --shading gooch --size 96x96", dir), 0.99);
    EXPECT_GE(matches_render(b, "builtin:sphere --shading " + next + " --size 96x96", dir), 0.99);
}

TEST(ViewCommand, LightPositionMatchesRenderLightPos) {
    TempDir dir;
    const std::string shot = dir.file("shot.png"), before = dir.file("before.png");
    CliResult r = run_view("builtin:sphere --shading phong --size 96x96 --script " +
                           script(dir, "gui off\nframes 1\nscreenshot " + before +
                                           "\nlight-pos -3,0.5,1\nframes 1\nscreenshot " + shot + "\n"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_LT(matching_fraction(read_png(before), read_png(shot)), 0.9);  // the highlight moved
    EXPECT_GE(matches_render(shot, "builtin:sphere --shading phong --size 96x96 --light-pos -3,0.5,1", dir), 0.99);
}

TEST(ViewCommand, SavedStyleRendersTheSameImage) {
    TempDir dir;
    const std::string shot = dir.file("shot.png"), style = dir.file("tuned.toml");
    CliResult r =
        run_view("builtin:torus --style cel-002 --size 96x96 --script " +
                 script(dir, "gui off\nset levels=0.2,0.5,0.9\nset shade-color=1,0.5,0.2\nframes 1\nscreenshot " + shot +
                                 "\nsave-style " + style + "\n"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_GE(matches_render(shot, "builtin:torus --style " + style + " --size 96x96", dir), 0.99);
    // The tuned value is in the file, so the render above did not just repeat cel-002.
    EXPECT_NE(slurp(style).find("0.2,0.5,0.9"), std::string::npos) << slurp(style);
}

TEST(ViewCommand, BadModelKeepsPreviousModelAndReportsError) {
    TempDir dir;
    const std::string a = dir.file("a.png"), b = dir.file("b.png");
    // A model that breaks after the script was checked, as a file opened from the Model panel
    // can be bad: the script itself overwrites it with a style file before opening it.
    const std::string model = dir.write("broken.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    CliResult r = run_view("builtin:sphere --size 64x64 --script " +
                           script(dir, "gui off\nframes 1\nscreenshot " + a + "\nsave-style " + model + "\nopen " +
                                           model + "\nframes 1\nscreenshot " + b + "\n"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("broken.obj: "), std::string::npos) << r.err;
    EXPECT_EQ(matching_fraction(read_png(a), read_png(b), 0), 1.0);
}

TEST(ViewCommand, NoDisplayIsOneLineErrorSuggestingRender) {
    CliResult r = run_cli("view builtin:sphere --frames 1", "env -u DISPLAY -u WAYLAND_DISPLAY");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("inkshade render"), std::string::npos) << r.err;
}

TEST(ViewCommand, BadScriptFailsBeforeTheWindowWithLineNumber) {
    TempDir dir;
    const std::string s = script(dir, "frames 1\nfly-away now\n");
    CliResult r = run_cli("view builtin:sphere --script " + s, "env -u DISPLAY");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find(s + ":2: unknown command 'fly-away'"), std::string::npos) << r.err;
    EXPECT_EQ(line_count(r.err), 1);
}

// What a script's lines name is checked before the window opens (no display here: a window
// would fail with exit 1): each is exit 2 with the script's FILE:LINE and one line.
TEST(ViewCommand, BadSetStyleOrModelInScriptFailsBeforeTheWindow) {
    TempDir dir;
    const std::string bad_model = dir.write("broken.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n");
    const struct {
        std::string script, message;
    } cases[] = {
        {"gui off\nframes 1\nset no-such-param=1\n", ":3: set no-such-param=1: model 'lambert' has no parameter"},
        {"style cel-002\nset levels=0.2,0.5\nset hull.width=2\n", ":3: set hull.width=2: the style draws no 'hull'"},
        {"frames 1\nstyle no-such-style\n", ":2: no-such-style: no such style file or built-in style"},
        {"open builtin:torus\nopen /nonexistent/model.obj\n", ":2: /nonexistent/model.obj: "},
        {"frames 2\n\n# broken\nopen " + bad_model + "\n", ":4: " + bad_model + ": "},
    };
    for (const auto& c : cases) {
        const std::string s = script(dir, c.script);
        CliResult r =
            run_cli("view builtin:sphere --shading lambert --script " + s, "env -u DISPLAY -u WAYLAND_DISPLAY");
        EXPECT_EQ(r.status, 2) << c.script << r.err;
        EXPECT_NE(r.err.find(s + c.message), std::string::npos) << c.script << r.err;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
    }
}

TEST(ViewCommand, ScriptIsCheckedAgainstTheStyleEachLineMeets) {
    TempDir dir;
    // Key 1 turns on the first line type `inkshade styles` lists, with its parameters.
    CliResult styles = run_cli("styles");
    const std::string header = "Line types (";
    const size_t at = styles.out.find('\n', styles.out.find(header)) + 1;
    ASSERT_NE(at, 0u) << styles.out;
    const std::string first_type = styles.out.substr(at + 2, styles.out.find(' ', at + 2) - at - 2);
    // `levels` is cel's, not lambert's; hull.width needs the hull lines toon draws; the first
    // type's width needs key 1, since lambert draws no lines.
    CliResult r = run_view("builtin:sphere --shading lambert --size 64x64 --script " +
                           script(dir,
                                  "gui off\nstyle cel-002\nset levels=0.2,0.5\nstyle toon\nset hull.width=2\n"
                                  "style lambert\nkey 1\nset " +
                                      first_type + ".width=2\nframes 1\nquit\n"));
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.find("has no parameter"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("draws no"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace inkshade::test
