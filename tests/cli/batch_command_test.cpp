// `inkshade batch`: models x views x styles into PNG/SVG + metadata; resume, --force, SIGTERM,
// shards, failed models, manifest errors, and the progress output.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <pty.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/file_tree.hpp"
#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"
#include "io/avatar_files.hpp"
#include "io/mesh_files.hpp"
#include "support/spawn.hpp"

namespace inkshade::test {
namespace {

namespace fs = std::filesystem;

size_t count_ending(const std::map<std::string, std::string>& files, const std::string& suffix) {
    size_t n = 0;
    for (const auto& [name, bytes] : files) n += name.ends_with(suffix);
    return n;
}

struct Counts {
    int total = -1, done = -1, skipped = -1, failed = -1;
};

// The summary line: "batch: N jobs: D done, S skipped, F failed in ...".
Counts summary(const std::string& out) {
    std::smatch m;
    Counts c;
    if (std::regex_search(out, m, std::regex(R"(batch: (\d+) jobs: (\d+) done, (\d+) skipped, (\d+) failed)"))) {
        c.total = std::stoi(m[1]);
        c.done = std::stoi(m[2]);
        c.skipped = std::stoi(m[3]);
        c.failed = std::stoi(m[4]);
    }
    return c;
}

ino_t inode(const fs::path& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 ? st.st_ino : 0;
}

// No temporary (".NAME.tmp-XXXXXX") or otherwise hidden file, and every PNG decodes and has
// its metadata beside it.
void expect_clean_outputs(const fs::path& dir) {
    for (const auto& [name, bytes] : files_under(dir)) {
        EXPECT_EQ(fs::path(name).filename().string().front() == '.', false) << "left behind: " << name;
        if (name.ends_with(".png")) {
            EXPECT_NO_THROW(read_png((dir / name).string())) << name;
            EXPECT_TRUE(fs::exists(dir / (name.substr(0, name.size() - 4) + ".json"))) << name;
        }
    }
}

class BatchCommand : public ::testing::Test {
protected:
    void SetUp() override {
        box_ = dir_.write("box.obj", cube_obj());
        block_ = dir_.write("block.ply", cube_ascii_ply());
        // 3 models x 4 views x 2 styles = 24 jobs.
        manifest_ = dir_.write("jobs.csv", "model,views,styles\n" + line(box_) + line(block_) +
                                               line("\"builtin:torus:major-segments=24,minor-segments=12\""));
    }
    static std::string line(const std::string& model) {
        return model + ",\"0:20,60:20,150:40,270:-10\",\"anime,toon\"\n";
    }
    std::string out(const std::string& name = "out") const { return dir_.file(name); }
    CliResult batch(const std::string& args) const { return run_cli("batch " + args); }

    TempDir dir_;
    std::string box_, block_, manifest_;
};

TEST_F(BatchCommand, RendersEveryModelViewAndStyleWithMetadata) {
    auto r = batch(manifest_ + " -o " + out() + " --size 64x64");
    ASSERT_EQ(r.status, 0) << r.err;
    const Counts c = summary(r.out);
    EXPECT_EQ(c.total, 24);
    EXPECT_EQ(c.done, 24);
    EXPECT_EQ(c.skipped, 0);
    EXPECT_EQ(c.failed, 0);
    // Not a terminal: one line per job.
    EXPECT_EQ(line_count(r.err), 24) << r.err;
    EXPECT_NE(r.err.find("[24/24] done "), std::string::npos) << r.err;

    const auto files = files_under(out());
    EXPECT_EQ(files.size(), 48u);
    EXPECT_EQ(count_ending(files, ".png"), 24u);
    EXPECT_EQ(count_ending(files, ".json"), 24u);
    expect_clean_outputs(out());
    for (const std::string model : {"box", "block", "torus-major-segments=24-minor-segments=12"})
        for (const std::string style : {"anime", "toon"})
            for (const std::string view : {"az000_el20", "az060_el20", "az150_el40", "az270_el-10"}) {
                const std::string stem = model + "/" + style + "/" + view;
                ASSERT_TRUE(files.count(stem + ".png")) << stem;
                const Image img = read_png(out() + "/" + stem + ".png");
                EXPECT_EQ(img.width, 64);
                EXPECT_EQ(img.height, 64);
                int drawn = 0;  // pixels that are not the white background
                for (int y = 0; y < 64; ++y)
                    for (int x = 0; x < 64; ++x)
                        drawn += img.pixel(x, y)[0] + img.pixel(x, y)[1] + img.pixel(x, y)[2] < 3 * 255;
                EXPECT_GT(drawn, 64 * 64 / 10) << stem;
            }

    const auto meta = nlohmann::json::parse(files.at("box/toon/az150_el40.json"));
    EXPECT_EQ(meta["job_hash"].get<std::string>().size(), 16u);
    EXPECT_EQ(meta["stem"], "box/toon/az150_el40");
    EXPECT_EQ(meta["source"], manifest_ + ":2");
    EXPECT_EQ(meta["model"]["path"], box_);
    EXPECT_EQ(meta["model"]["bytes"], fs::file_size(box_));
    EXPECT_EQ(meta["model"]["triangles"], 12);
    EXPECT_EQ(meta["view"]["azimuth_degrees"], 150.0);
    EXPECT_EQ(meta["view"]["elevation_degrees"], 40.0);
    EXPECT_EQ(meta["camera"]["eye"].size(), 3u);
    EXPECT_EQ(meta["camera"]["fov_degrees"], 30.0);
    EXPECT_EQ(meta["camera"]["orthographic"], false);
    EXPECT_EQ(meta["camera"]["view_matrix"].size(), 4u);
    EXPECT_EQ(meta["camera"]["projection_matrix"][3][2], -1.0);  // perspective: w = -z_eye
    EXPECT_EQ(meta["image"]["width"], 64);
    EXPECT_EQ(meta["image"]["samples"], 4);
    EXPECT_EQ(meta["style"]["name"], "toon");
    EXPECT_NE(meta["style"]["toml"].get<std::string>().find("[shading]"), std::string::npos);
    EXPECT_TRUE(meta["lines"].is_array());
    EXPECT_EQ(meta["outputs"]["png"], "az150_el40.png");
    EXPECT_FALSE(meta["inkshade"].get<std::string>().empty());
    EXPECT_TRUE(meta["timings_ms"].contains("render"));
    EXPECT_TRUE(nlohmann::json::parse(
                    files.at("torus-major-segments=24-minor-segments=12/anime/az000_el20.json"))["model"]["bytes"]
                    .is_null());
}

TEST_F(BatchCommand, ResumeSkipsCompleteJobsForceRendersTheSameBytes) {
    ASSERT_EQ(batch(manifest_ + " -o " + out() + " --size 64x64 -q").status, 0);
    const auto first = files_under(out());
    const ino_t png_inode = inode(out() + "/block/anime/az060_el20.png");

    auto r = batch(manifest_ + " -o " + out() + " --size 64x64 -q");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(summary(r.out).skipped, 24) << r.out;
    EXPECT_EQ(summary(r.out).done, 0);
    EXPECT_EQ(inode(out() + "/block/anime/az060_el20.png"), png_inode);  // not rewritten
    EXPECT_EQ(r.err, "");                                                // -q: nothing but failures

    // A missing output or a stale hash makes a job incomplete.
    fs::remove(out() + "/box/toon/az000_el20.png");
    {
        std::ofstream meta(out() + "/box/anime/az000_el20.json");
        meta << "{\"job_hash\": \"0000000000000000\"}";
    }
    r = batch(manifest_ + " -o " + out() + " --size 64x64 -q");
    EXPECT_EQ(summary(r.out).done, 2) << r.out;
    EXPECT_EQ(summary(r.out).skipped, 22);
    const auto redone = files_under(out());
    ASSERT_EQ(redone.size(), first.size());
    for (const auto& [name, bytes] : first)
        if (!name.ends_with(".json")) {
            EXPECT_EQ(redone.at(name), bytes) << name;  // metadata: timings differ
        }

    r = batch(manifest_ + " -o " + out() + " --size 64x64 -q --force");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(summary(r.out).done, 24) << r.out;
    EXPECT_NE(inode(out() + "/block/anime/az060_el20.png"), png_inode);
    const auto again = files_under(out());
    ASSERT_EQ(again.size(), first.size());
    for (const auto& [name, bytes] : first)
        if (!name.ends_with(".json")) {
            EXPECT_EQ(again.at(name), bytes) << name << " differs after --force";
        }

    // Another size is another job: the hash changes and everything renders again.
    r = batch(manifest_ + " -o " + out() + " --size 48x32 -q");
    EXPECT_EQ(summary(r.out).done, 24) << r.out;
    EXPECT_EQ(read_png(out() + "/box/toon/az000_el20.png").width, 48);
}

// 80 small jobs (two models x 20 views x 2 styles) in `dir`: enough to signal a batch midway.
std::string write_long_manifest(TempDir& dir) {
    return dir.write("long.csv",
                     "model,views,styles\n"
                     "builtin:teapot,turntable:20,\"anime,toon\"\n"
                     "builtin:torus,turntable:20,\"anime,toon\"\n");
}

// `inkshade batch MANIFEST -o OUT --size 32x32` in the background (stdout and stderr to files in
// `dir`), returned once three jobs are complete (or after two minutes); its pid, ≤ 0 on failure.
pid_t start_batch_until_three_done(TempDir& dir, const std::string& manifest, const std::string& out) {
    const pid_t pid = spawn({"batch", manifest, "-o", out, "--size", "32x32"}, dir.file("stdout"), dir.file("stderr"));
    if (pid <= 0) return pid;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (count_ending(files_under(out), ".json") < 3 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return pid;
}

TEST_F(BatchCommand, SigtermStopsCleanlyAndResumeRendersOnlyTheRest) {
    const std::string manifest = write_long_manifest(dir_);
    const pid_t pid = start_batch_until_three_done(dir_, manifest, out());
    ASSERT_GT(pid, 0);
    ASSERT_EQ(kill(pid, SIGTERM), 0);
    int raw = 0;
    ASSERT_EQ(waitpid(pid, &raw, 0), pid);
    ASSERT_TRUE(WIFEXITED(raw)) << "killed by signal " << WTERMSIG(raw);
    EXPECT_EQ(WEXITSTATUS(raw), 143) << slurp(dir_.file("stderr"));
    const std::string stopped = slurp(dir_.file("stdout"));
    EXPECT_NE(stopped.find("stopped by SIGTERM"), std::string::npos) << stopped;
    const Counts c = summary(stopped);
    EXPECT_EQ(c.total, 80);
    EXPECT_GE(c.done, 3);
    EXPECT_LT(c.done, 80) << "finished before the signal: the test needs more jobs";

    expect_clean_outputs(out());
    const auto before = files_under(out());
    EXPECT_EQ(count_ending(before, ".json"), size_t(c.done));  // every finished job is complete
    std::map<std::string, ino_t> inodes;
    for (const auto& [name, bytes] : before) inodes[name] = inode(out() + "/" + name);

    auto r = run_cli("batch " + manifest + " -o " + out() + " --size 32x32 -q");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(summary(r.out).skipped, c.done) << r.out;
    EXPECT_EQ(summary(r.out).done, 80 - c.done);
    for (const auto& [name, ino] : inodes) EXPECT_EQ(inode(out() + "/" + name), ino) << name << " was rendered again";
    expect_clean_outputs(out());
    EXPECT_EQ(count_ending(files_under(out()), ".png"), 80u);
}

// A worker killed outright (SIGKILL, no chance to clean up) loses at most its in-flight job:
// every output under its final name is complete (written to a temporary, then renamed), at most
// the temporaries of one job are left, and the rerun renders exactly the jobs without metadata.
TEST_F(BatchCommand, SigkillLosesAtMostTheJobInFlightAndTheRerunCompletesTheRest) {
    const std::string manifest = write_long_manifest(dir_);
    const pid_t pid = start_batch_until_three_done(dir_, manifest, out());
    ASSERT_GT(pid, 0);
    ASSERT_EQ(kill(pid, SIGKILL), 0);
    int raw = 0;
    ASSERT_EQ(waitpid(pid, &raw, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(raw));

    const auto left = files_under(out());
    std::set<std::string> temp_stems;  // the outputs the temporaries were for, by stem
    size_t complete = 0;
    for (const auto& [name, bytes] : left) {
        const fs::path p(name);
        const std::string file = p.filename().string();
        if (file.front() == '.') {
            ASSERT_NE(file.find(".tmp-"), std::string::npos) << name;
            temp_stems.insert((p.parent_path() / fs::path(file.substr(1, file.find(".tmp-") - 1)).stem()).string());
            continue;
        }
        if (name.ends_with(".png")) {
            EXPECT_NO_THROW(read_png(out() + "/" + name)) << name;
        }
        if (name.ends_with(".json")) {
            EXPECT_NO_THROW(nlohmann::json::parse(bytes)) << name;
            ++complete;
        }
    }
    EXPECT_LE(temp_stems.size(), 1u) << "temporaries of more than the job in flight";
    ASSERT_GE(complete, 3u);
    ASSERT_LT(complete, 80u) << "finished before the signal: the test needs more jobs";

    auto r = run_cli("batch " + manifest + " -o " + out() + " --size 32x32 -q");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(summary(r.out).skipped, int(complete)) << r.out;
    EXPECT_EQ(summary(r.out).done, 80 - int(complete));
    EXPECT_EQ(count_ending(files_under(out()), ".json"), 80u);
}

TEST_F(BatchCommand, ShardsTogetherGiveTheUnshardedSetWithoutOverlap) {
    const std::string common = " --size 32x32 -q --styles toon";
    const std::string manifest =
        dir_.write("views.csv", "model,views\n" + box_ + ",\"0:0,90:0,180:0,270:0\"\n" + block_ +
                                    ",\"0:0,90:0,180:0,270:0\"\nbuiltin:sphere,orbit2x2\n");
    ASSERT_EQ(batch(manifest + " -o " + out("all") + common).status, 0);
    const auto all = files_under(out("all"));
    EXPECT_EQ(all.size(), 24u);
    std::map<std::string, std::string> joined;
    for (int k = 1; k <= 3; ++k) {
        const std::string dir = out("shard" + std::to_string(k));
        auto r = batch(manifest + " -o " + dir + common + " --shard " + std::to_string(k) + "/3");
        ASSERT_EQ(r.status, 0) << r.err;
        EXPECT_EQ(summary(r.out).total, 4) << r.out;  // 12 jobs in 3 blocks
        for (const auto& [name, bytes] : files_under(dir)) {
            EXPECT_FALSE(joined.count(name)) << name << " is in two shards";
            joined[name] = bytes;
        }
    }
    ASSERT_EQ(joined.size(), all.size());
    for (const auto& [name, bytes] : all) {
        ASSERT_TRUE(joined.count(name)) << name << " is in no shard";
        if (name.ends_with(".png")) {
            EXPECT_EQ(joined.at(name), bytes) << name;
        }
    }
}

TEST_F(BatchCommand, BadModelIsReportedOnceAndTheRestCompleteWithExit1) {
    const std::string bad = dir_.write("bad.stl", "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0");
    const std::string manifest =
        dir_.write("mixed.csv", "model,views,styles\n" + bad + ",turntable:3,\"anime,toon\"\n" +
                                    dir_.file("missing.obj") + ",0:0,toon\n" + box_ + ",turntable:2,toon\n");
    auto r = batch(manifest + " -o " + out() + " --size 32x32 -q");
    EXPECT_EQ(r.status, 1) << r.err;
    const Counts c = summary(r.out);
    EXPECT_EQ(c.total, 9);
    EXPECT_EQ(c.done, 2);
    EXPECT_EQ(c.failed, 7);
    // One line per failed model, with the reason and the jobs it cost.
    EXPECT_EQ(line_count(r.err), 2) << r.err;
    EXPECT_NE(r.err.find("inkshade: " + bad + ": "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("(6 jobs failed)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("missing.obj: cannot open file"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("(1 job failed)"), std::string::npos) << r.err;
    const auto files = files_under(out());
    EXPECT_EQ(files.size(), 4u);
    EXPECT_TRUE(files.count("box/toon/az180_el20.png"));
    expect_clean_outputs(out());
}

TEST_F(BatchCommand, BadManifestOrOptionsAreExit2WithOneLine) {
    const std::vector<std::pair<std::string, std::string>> manifests = {
        {"model,views\n" + box_ + ",0:0\n" + box_ + ",sideways\n", "bad.csv:3: view 'sideways'"},
        {"model,styles\n" + box_ + ",glossy\n", "bad.csv:2: "},
        {"model,colour\n" + box_ + ",red\n", "bad.csv:1: unknown column 'colour'"},
        {"model\n", "bad.csv: no jobs"},
    };
    for (const auto& [text, expected] : manifests) {
        const std::string path = dir_.write("bad.csv", text);
        auto r = batch(path + " -o " + out());
        EXPECT_EQ(r.status, 2) << text;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
        EXPECT_NE(r.err.find("inkshade: " + dir_.file(expected)), std::string::npos) << r.err;
    }
    const std::string jsonl = dir_.write("bad.jsonl", "{\"model\": \"" + box_ + "\"}\n{\"model\": \n");
    auto r = batch(jsonl + " -o " + out());
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find(jsonl + ":2: not valid JSON"), std::string::npos) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;

    for (const std::string& args : {std::string("-o ") + out(), manifest_, manifest_ + " --models . -o " + out(),
                                    manifest_ + " --shard 4/3 -o " + out(), manifest_ + " --shard 0/3 -o " + out(),
                                    manifest_ + " --views orbit -o " + out(), manifest_ + " --format gif -o " + out(),
                                    manifest_ + " --size 0x1 -o " + out(), manifest_ + " -o " + box_,
                                    dir_.file("nope.csv") + " -o " + out(), "--models " + box_ + " -o " + out()}) {
        r = batch(args);
        EXPECT_EQ(r.status, 2) << args << ": " << r.err;
        EXPECT_EQ(line_count(r.err), 1) << args << ": " << r.err;
    }
    EXPECT_FALSE(fs::exists(out()));  // nothing written
}

TEST_F(BatchCommand, OutputsEqualRenderAndLinesCommands) {
    const std::string manifest = dir_.write("one.jsonl",
                                            "{\"model\": \"builtin:teapot\", \"views\": \"50:25\", "
                                            "\"styles\": \"anime\", \"format\": \"png,svg\"}\n");
    ASSERT_EQ(batch(manifest + " -o " + out() + " --size 80x60 -q").status, 0);
    const std::string camera = " --style anime --size 80x60 --azimuth 50 --elevation 25 ";
    ASSERT_EQ(run_cli("render builtin:teapot" + camera + "-o " + dir_.file("r.png")).status, 0);
    ASSERT_EQ(run_cli("lines builtin:teapot" + camera + "-o " + dir_.file("l.svg")).status, 0);
    EXPECT_EQ(slurp(out() + "/teapot/anime/az050_el25.png"), slurp(dir_.file("r.png")));
    EXPECT_EQ(slurp(out() + "/teapot/anime/az050_el25.svg"), slurp(dir_.file("l.svg")));
    const auto meta = nlohmann::json::parse(slurp(out() + "/teapot/anime/az050_el25.json"));
    EXPECT_EQ(meta["outputs"]["svg"], "az050_el25.svg");
    EXPECT_EQ(meta["svg_lines"], nlohmann::json({"contour", "suggestive", "crease", "border"}));
}

// A dataset of an animation: each row's time (and pose) gives the image `inkshade render` gives
// with the same --animation, --time, --expression and --morph, and the metadata records it. No
// style is named: the VRM takes its own (`vrm`), as `inkshade render` without --style does.
TEST_F(BatchCommand, PosePerJobGivesTheRenderCommandsImage) {
    const std::string model = dir_.write("avatar.vrm", avatar(AvatarFormat::Vrm1).glb());
    const std::string manifest = dir_.write("frames.csv", "model,name,time,expression\n" + model + ",t0,0,\n" + model +
                                                              ",t1,1,\n" + model + ",t2,2,happy=1\n");
    const auto r = batch(manifest + " -o " + out() + " --animation wave --morph blink=0.5 --size 96x96 --views 0:0 -q");
    ASSERT_EQ(r.status, 0) << r.err;
    std::set<std::string> images;
    for (const char* t : {"0", "1", "2"}) {
        SCOPED_TRACE(t);
        const std::string stem = out() + "/t" + t + "/vrm/az000_el00";
        const std::string expression = std::string(t) == "2" ? " --expression happy=1" : "";
        const auto cli = run_cli("render " + model + " --animation wave --morph blink=0.5 --time " + t + expression +
                                 " --size 96x96 --azimuth 0 --elevation 0 -o " + dir_.file("r.png"));
        ASSERT_EQ(cli.status, 0) << cli.err;
        EXPECT_EQ(slurp(stem + ".png"), slurp(dir_.file("r.png")));
        images.insert(slurp(stem + ".png"));
        const auto meta = nlohmann::json::parse(slurp(stem + ".json"));
        EXPECT_EQ(meta["time"], std::stod(t));
        EXPECT_EQ(meta["animation"], "wave");
        EXPECT_EQ(meta["morphs"], nlohmann::json({{"blink", 0.5}}));
        EXPECT_EQ(meta.contains("expressions"), expression.size() > 0);
    }
    EXPECT_EQ(images.size(), 3u);  // the arm moved
    // A job with a name the file does not have fails alone, with the loader's message.
    const std::string bad = dir_.write("bad.csv", "model,name,animation\n" + model + ",x,wav\n");
    const auto failed = batch(bad + " -o " + out() + " --size 32x32 -q");
    EXPECT_NE(failed.status, 0);
    EXPECT_NE(failed.err.find("no animation 'wav' (did you mean 'wave'?)"), std::string::npos) << failed.err;
}

// Occlusion levels per job give the SVG `inkshade lines --occlusion-levels` gives (its dashed
// layers), in the metadata too; the PNG still draws visible lines only.
TEST_F(BatchCommand, OcclusionLevelsGiveTheLinesCommandsSvg) {
    const std::string manifest = dir_.write("levels.csv",
                                            "model,views,styles,format,up-axis,occlusion-levels\n"
                                            "builtin:torus,20:20,ink-vector,\"png,svg\",z,0-1\n");
    ASSERT_EQ(batch(manifest + " -o " + out() + " --size 120x90 -q").status, 0);
    const std::string camera = " --style ink-vector --size 120x90 --up-axis z --azimuth 20 --elevation 20 ";
    ASSERT_EQ(run_cli("lines builtin:torus" + camera + "--occlusion-levels 0-1 -o " + dir_.file("l.svg")).status, 0);
    ASSERT_EQ(run_cli("render builtin:torus" + camera + "-o " + dir_.file("r.png")).status, 0);
    const std::string svg = slurp(out() + "/torus/ink-vector/az020_el20.svg");
    EXPECT_EQ(svg, slurp(dir_.file("l.svg")));
    EXPECT_NE(svg.find("<g id=\"contour-hidden-1\""), std::string::npos) << "a torus hides part of its contour";
    EXPECT_EQ(slurp(out() + "/torus/ink-vector/az020_el20.png"), slurp(dir_.file("r.png")));
    const auto meta = nlohmann::json::parse(slurp(out() + "/torus/ink-vector/az020_el20.json"));
    EXPECT_EQ(meta["occlusion_levels"], nlohmann::json({0, 1}));
}

TEST_F(BatchCommand, ModelsDirectoryWithDryRunListsJobsAndWritesNothing) {
    fs::create_directories(dir_.path() / "models/sub");
    dir_.write("models/a.obj", cube_obj());
    dir_.write("models/sub/b.ply", cube_ascii_ply());
    auto r = batch("--models " + dir_.file("models") + " --views orbit8x3 --styles anime,toon --dry-run -o " + out());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(line_count(r.out), 96);
    EXPECT_NE(r.out.find("a/anime/az000_el00\t" + dir_.file("models/a.obj") + "\tanime\taz000_el00\t512x512\tpng\n"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("sub/b/toon/az315_el60\t"), std::string::npos);
    EXPECT_FALSE(fs::exists(out()));
    r = batch("--models " + dir_.file("models") + " --views orbit8x3 --styles anime,toon --dry-run --shard 2/2");
    EXPECT_EQ(line_count(r.out), 48);
    EXPECT_EQ(r.out.find("a/anime"), std::string::npos);  // contiguous: shard 2 is model b
}

// On a terminal: one line redrawn in place with the count, the rate and the ETA.
TEST_F(BatchCommand, ProgressOnATerminalIsOneUpdatingLine) {
    int master = -1;
    const pid_t pid = forkpty(&master, nullptr, nullptr, nullptr);
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        const std::string o = out();
        execl(INKSHADE_BIN, INKSHADE_BIN, "batch", manifest_.c_str(), "-o", o.c_str(), "--size", "32x32",
              static_cast<char*>(nullptr));
        _exit(127);
    }
    std::string text;
    char buf[4096];
    ssize_t n = 0;
    while ((n = read(master, buf, sizeof buf)) > 0) text.append(buf, size_t(n));
    int raw = 0;
    waitpid(pid, &raw, 0);
    close(master);
    EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << text;
    EXPECT_NE(text.find("\r\033[K["), std::string::npos) << text;
    EXPECT_NE(text.find("images/s, ETA"), std::string::npos) << text;
    EXPECT_EQ(text.find("] done "), std::string::npos) << text;  // no per-job lines
    EXPECT_NE(text.find("batch: 24 jobs: 24 done"), std::string::npos) << text;
    EXPECT_EQ(line_count(text), 1) << text;  // just the summary ends a line
}

}  // namespace
}  // namespace inkshade::test
