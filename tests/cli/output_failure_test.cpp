// A write that fails half way (a full disk) is a one-line error, and leaves neither the output
// nor a temporary behind, for every file the commands write. The failure is made by a file-size
// limit (RLIMIT_FSIZE with SIGXFSZ ignored, so write() fails with EFBIG as it fails with ENOSPC
// on a full disk): it needs no root, no mount and no free-space games.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli/run_cli.hpp"

namespace inkshade::test {
namespace {

namespace fs = std::filesystem;

// /bin/sh's ulimit -f counts 512-byte blocks (dash) or 1024-byte ones (bash): either way every
// output below is larger, and the one-line message on stderr fits.
constexpr const char* kSmallFileLimit = "trap '' XFSZ; ulimit -f 1;";

void expect_write_failure(const std::string& args, const TempDir& dir, const std::string& failing_file) {
    const CliResult r = run_cli(args, kSmallFileLimit);
    EXPECT_EQ(r.status, 1) << args << "\n" << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(failing_file + ": cannot write file (File too large)"), std::string::npos) << r.err;
    for (const auto& e : fs::recursive_directory_iterator(dir.path())) {
        const std::string name = e.path().filename().string();
        EXPECT_EQ(name.find(".tmp-"), std::string::npos) << "temporary left behind: " << e.path();
        EXPECT_NE(e.path().string(), failing_file) << "partial output";
    }
}

TEST(OutputFailure, FullDiskWhileWritingIsOneLineErrorAndNoPartialFile) {
    {
        TempDir dir;
        expect_write_failure("render builtin:teapot --size 256x256 -o " + dir.file("a.png"), dir, dir.file("a.png"));
    }
    {
        TempDir dir;
        expect_write_failure("lines builtin:teapot -o " + dir.file("a.svg"), dir, dir.file("a.svg"));
    }
    {
        // The style file is written after the PNG: the PNG is complete, the style is not there.
        TempDir dir;
        const CliResult r = run_cli("render builtin:sphere --size 8x8 --style anime -o " + dir.file("a.png") +
                                        " --save-style " + dir.file("s.toml"),
                                    kSmallFileLimit);
        EXPECT_EQ(r.status, 1) << r.err;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
        EXPECT_NE(r.err.find(dir.file("s.toml") + ": cannot write file"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir.file("s.toml")));
        for (const auto& e : fs::directory_iterator(dir.path()))
            EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
    }
}

TEST(OutputFailure, BatchReportsTheFailedJobsAndLeavesNoPartialFile) {
    TempDir dir;
    const std::string manifest =
        dir.write("jobs.csv", "model,views,styles,size\nbuiltin:teapot,0:20;90:20,lambert,256x256\n");
    const CliResult r = run_cli("batch " + manifest + " -o " + dir.file("out"), kSmallFileLimit);
    EXPECT_NE(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("2 failed"), std::string::npos) << r.out;
    for (const auto& e : fs::recursive_directory_iterator(dir.path())) {
        EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
        EXPECT_NE(e.path().extension(), ".png") << "partial image " << e.path();
    }
    // Without the limit the same batch resumes into complete outputs.
    const CliResult again = run_cli("batch " + manifest + " -o " + dir.file("out"));
    EXPECT_EQ(again.status, 0) << again.err;
    EXPECT_NE(again.out.find("2 done"), std::string::npos) << again.out;
}

}  // namespace
}  // namespace inkshade::test
