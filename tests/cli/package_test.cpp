// The installed CMake package: `cmake --install` into a scratch prefix, then examples/ configured
// with find_package(inkshade) against it, built and run; its picture must be the CLI's.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

int shell(const std::string& command, const std::string& log) {
    const int raw = std::system((command + " >>" + log + " 2>&1").c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
}

TEST(Package, ExampleBuildsAgainstInstalledPackageAndRendersTheCliImage) {
    TempDir dir;
    const std::string build_dir = std::filesystem::path(INKSHADE_BIN).parent_path().string();
    const std::string prefix = dir.file("prefix"), examples = dir.file("examples"), log = dir.file("log");
    ASSERT_EQ(shell("cmake --install '" + build_dir + "' --prefix '" + prefix + "'", log), 0) << slurp(log);
    ASSERT_TRUE(std::filesystem::exists(prefix + "/include/inkshade/renderer.hpp"));
    ASSERT_TRUE(std::filesystem::exists(prefix + "/lib/cmake/inkshade/inkshadeConfig.cmake"));
    ASSERT_EQ(shell("cmake -S '" + std::string(INKSHADE_SOURCE_DIR) + "/examples' -B '" + examples +
                        "' -G Ninja -DCMAKE_PREFIX_PATH='" + prefix + "'",
                    log),
              0)
        << slurp(log);
    ASSERT_EQ(shell("cmake --build '" + examples + "'", log), 0) << slurp(log);
    // Linked against the installed library, not the build tree's.
    ASSERT_EQ(shell("ldd '" + examples + "/render_teapot' | grep -q '" + prefix + "/lib/libinkshade.so'", log), 0)
        << slurp(log);

    const std::string stem = dir.file("teapot");
    ASSERT_EQ(shell("'" + examples + "/render_teapot' '" + stem + "'", log), 0) << slurp(log);
    const Image image = read_png(stem + ".png");
    ASSERT_EQ(image.width, 512);
    ASSERT_EQ(image.height, 512);
    int inked = 0;  // dark outline pixels of the anime style
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) inked += image.pixel(x, y)[0] < 40;
    EXPECT_GT(inked, 2000);
    EXPECT_NE(slurp(stem + ".svg").find("<path"), std::string::npos);

    const std::string cli_png = dir.file("cli.png");
    const CliResult r = run_cli("render builtin:teapot --style anime --size 512x512 -o '" + cli_png + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(cli_png), slurp(stem + ".png"));
    const std::string cli_svg = dir.file("cli.svg");
    const CliResult l = run_cli("lines builtin:teapot --style ink-vector --size 512x512 -o '" + cli_svg + "'");
    ASSERT_EQ(l.status, 0) << l.err;
    EXPECT_EQ(slurp(cli_svg), slurp(stem + ".svg"));
}

}  // namespace
}  // namespace inkshade::test
