// `inkshade batch --layout webdataset`: tar shards read back by Python's tarfile equal the folder
// layout of the same jobs; SIGKILL and resume; --verify in both layouts; bad options.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/file_tree.hpp"
#include "cli/run_cli.hpp"
#include "io/tar_reader.hpp"
#include "support/spawn.hpp"

namespace inkshade::test {
namespace {

namespace fs = std::filesystem;

// The shard files PREFIX-NNNNNN.tar in `dir`, sorted.
std::vector<std::string> shards_in(const std::string& dir, const std::string& prefix = "shard") {
    std::vector<std::string> shards;
    const std::regex name(prefix + R"(-\d{6}\.tar)");
    std::error_code ec;  // none yet while the batch starts
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (std::regex_match(e.path().filename().string(), name)) shards.push_back(e.path().string());
    std::sort(shards.begin(), shards.end());
    return shards;
}

// The members of a shard, by name, as Inkshade's own reader sees them.
std::vector<std::string> members(const std::string& shard) {
    io::TarReader reader(shard);
    std::vector<std::string> names;
    while (const auto m = reader.next()) names.push_back(m->name);
    return names;
}

std::string key_of(std::string stem) {
    for (char& c : stem)
        if (c == '.') c = '_';
    return stem;
}

// The metadata without its timings, the one part of a job's files that differs between runs.
nlohmann::json without_timings(const std::string& text) {
    nlohmann::json j = nlohmann::json::parse(text);
    j.erase("timings_ms");
    return j;
}

std::vector<std::string> dry_run_stems(const std::string& manifest) {
    const CliResult r = run_cli("batch " + manifest + " --dry-run");
    std::vector<std::string> stems;
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);) stems.push_back(line.substr(0, line.find('\t')));
    return stems;
}

struct Counts {
    int done = -1, skipped = -1;
};

Counts summary(const std::string& out) {
    std::smatch m;
    Counts c;
    if (std::regex_search(out, m, std::regex(R"(batch: \d+ jobs: (\d+) done, (\d+) skipped)"))) {
        c.done = std::stoi(m[1]);
        c.skipped = std::stoi(m[2]);
    }
    return c;
}

class WebDatasetBatch : public ::testing::Test {
protected:
    std::string out(const std::string& name = "out") const { return dir_.file(name); }
    TempDir dir_;
};

// Every file of the folder layout comes back from the shards, read by Python's tarfile, with the
// same bytes (the metadata: but for its timings) under KEY + the same extension; a sample's files
// are consecutive, none spans two shards, and a shard passes the size only when it holds one
// sample. The long stem (over ustar's 255 bytes) takes a pax header.
TEST_F(WebDatasetBatch, ShardsReadBackByTarfileEqualTheFolderLayout) {
    const std::string long_stem = "long/" + std::string(130, 'd') + "/" + std::string(140, 'e') + ".v";
    const std::string manifest = dir_.write(
        "jobs.jsonl",
        "{\"model\": \"builtin:sphere\", \"views\": \"0:20,22.5:30\", \"styles\": \"toon\", \"format\": \"png,svg\", "
        "\"aov\": \"depth,normal\"}\n"
        "{\"model\": \"builtin:torus\", \"views\": \"90:10\", \"styles\": \"ink\", \"output\": \"" +
            long_stem + "\"}\n");
    const std::string common = " --size 48x48 -q";
    ASSERT_EQ(run_cli("batch " + manifest + " -o " + out("folder") + common).status, 0);
    const uint64_t limit = 30000;
    const CliResult r =
        run_cli("batch " + manifest + " -o " + out("wds") + common + " --layout webdataset --shard-size 30kB");
    ASSERT_EQ(r.status, 0) << r.err;

    const std::vector<std::string> shards = shards_in(out("wds"));
    ASSERT_GE(shards.size(), 2u) << "the test needs samples in several shards";
    EXPECT_EQ(files_under(out("wds")).size(), shards.size()) << "only the shards are left";
    std::string args;
    for (const std::string& s : shards) args += " '" + s + "'";
    const std::string listing = dir_.file("listing");
    const std::string command = "python3 '" + std::string(INKSHADE_SOURCE_DIR) + "/tests/cli/read_shards.py' '" +
                                out("extracted") + "'" + args + " >'" + listing + "'";
    ASSERT_EQ(std::system(command.c_str()), 0) << slurp(listing);
    for (const std::string& s : shards) {
        std::set<std::string> keys;
        for (const std::string& m : members(s)) keys.insert(m.substr(0, m.find('.', m.rfind('/') + 1)));
        if (keys.size() > 1) {
            EXPECT_LE(fs::file_size(s), limit) << s;
        }
    }

    const auto folder = files_under(out("folder")), extracted = files_under(out("extracted"));
    const std::vector<std::string> stems = dry_run_stems(manifest);
    ASSERT_EQ(stems.size(), 3u);
    EXPECT_NE(std::find(stems.begin(), stems.end(), long_stem), stems.end());
    size_t compared = 0;
    for (const std::string& stem : stems) {
        for (const auto& [name, bytes] : folder) {
            if (!name.starts_with(stem + ".")) continue;
            const std::string extension = name.substr(stem.size()), member = key_of(stem) + extension;
            ASSERT_TRUE(extracted.count(member)) << member << " (for " << name << ")";
            if (name == stem + ".json")
                EXPECT_EQ(without_timings(extracted.at(member)), without_timings(bytes)) << name;
            else
                EXPECT_TRUE(extracted.at(member) == bytes) << name << " differs from " << member;
            ++compared;
        }
    }
    EXPECT_EQ(compared, folder.size());
    EXPECT_EQ(extracted.size(), folder.size());
    EXPECT_EQ(compared, 2 * 6 + 2u);  // png, svg, depth.exr, normal.png, camera.json, json; png, json
}

// A worker killed outright leaves its closed shards, at most the open shard's temporary and the
// staging folder of the job in flight. The rerun removes both, keeps the closed shards (the last
// one reopened: its old bytes stay its beginning), skips their jobs and renders the rest: every
// job once in the shards, and the same job hashes as an uninterrupted run.
TEST_F(WebDatasetBatch, SigkillKeepsClosedShardsAndTheRerunCompletesTheRest) {
    const std::string manifest = dir_.write("long.csv",
                                            "model,views,styles\n"
                                            "builtin:teapot,turntable:20,\"anime,toon\"\n"
                                            "builtin:torus,turntable:20,\"anime,toon\"\n");
    const std::vector<std::string> args = {"batch", manifest,   "-o",         out(),          "--size",
                                           "32x32", "--layout", "webdataset", "--shard-size", "24kB"};
    const pid_t pid = spawn(args, dir_.file("stdout"), dir_.file("stderr"));
    ASSERT_GT(pid, 0);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (shards_in(out()).size() < 3 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_EQ(kill(pid, SIGKILL), 0);
    int raw = 0;
    ASSERT_EQ(waitpid(pid, &raw, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(raw)) << slurp(dir_.file("stderr"));

    std::map<std::string, std::string> before;
    size_t complete = 0, temporaries = 0;
    std::set<std::string> staged_stems;
    for (const auto& [name, bytes] : files_under(out())) {
        if (name.starts_with(".shard.staging/")) {
            const std::string file = fs::path(name).filename().string();
            staged_stems.insert(fs::path(name).parent_path().string() + "/" + file.substr(0, file.find('.')));
        } else if (name.starts_with(".shard-")) {
            EXPECT_NE(name.find(".tar.tmp-"), std::string::npos) << name;
            ++temporaries;
        } else {
            ASSERT_TRUE(std::regex_match(name, std::regex(R"(shard-\d{6}\.tar)"))) << name;
            before[name] = bytes;
            for (const std::string& m : members(out() + "/" + name))  // KEY.json: one sample's metadata
                complete += std::count(m.begin(), m.end(), '.') == 1 && m.ends_with(".json");
        }
    }
    EXPECT_LE(temporaries, 1u);
    EXPECT_LE(staged_stems.size(), 1u) << "staged files of more than the job in flight";
    ASSERT_GE(before.size(), 3u);
    ASSERT_LT(complete, 80u) << "finished before the signal: the test needs more jobs";

    const CliResult r =
        run_cli("batch " + manifest + " -o " + out() + " --size 32x32 --layout webdataset --shard-size 24kB -q");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(summary(r.out).skipped, int(complete)) << r.out;
    EXPECT_EQ(summary(r.out).done, 80 - int(complete));
    const auto after = files_under(out());
    for (const auto& [name, bytes] : before) {
        ASSERT_TRUE(after.count(name)) << name;
        if (name == before.rbegin()->first)
            EXPECT_EQ(after.at(name).substr(0, bytes.size() - 1024), bytes.substr(0, bytes.size() - 1024)) << name;
        else
            EXPECT_TRUE(after.at(name) == bytes) << name << " was written again";
    }
    std::map<std::string, std::string> hashes;  // key -> job hash in the shards
    for (const std::string& shard : shards_in(out())) {
        io::TarReader reader(shard);
        while (const auto m = reader.next())
            if (std::count(m->name.begin(), m->name.end(), '.') == 1 && m->name.ends_with(".json")) {
                const std::string key = m->name.substr(0, m->name.size() - 5);
                EXPECT_FALSE(hashes.count(key)) << key << " twice";
                hashes[key] = nlohmann::json::parse(reader.read(*m))["job_hash"];
            }
    }
    EXPECT_EQ(hashes.size(), 80u);
    EXPECT_EQ(after.size(), shards_in(out()).size()) << "no temporary or staging file is left";

    // The hashes of a folder run of the same jobs: a resumed job is the same job.
    ASSERT_EQ(run_cli("batch " + manifest + " -o " + out("folder") + " --size 32x32 -q").status, 0);
    for (const auto& [name, bytes] : files_under(out("folder"))) {
        if (!name.ends_with(".json")) continue;
        EXPECT_EQ(hashes[key_of(name.substr(0, name.size() - 5))], nlohmann::json::parse(bytes)["job_hash"]) << name;
    }
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// --verify passes a complete output and names, one line each, a removed file and a truncated
// one in the folder layout, and a truncated shard and a removed shard in the WebDataset layout.
TEST_F(WebDatasetBatch, VerifyFindsRemovedAndTruncatedFilesInBothLayouts) {
    const std::string manifest =
        dir_.write("jobs.csv", "model,views,styles,aov\nbuiltin:sphere,\"0:20,90:20,180:20\",toon,depth\n");
    const std::string common = " --size 32x32 -q";
    ASSERT_EQ(run_cli("batch " + manifest + " -o " + out("folder") + common).status, 0);
    CliResult v = run_cli("batch " + manifest + " --verify " + out("folder") + common);
    EXPECT_EQ(v.status, 0) << v.out << v.err;
    EXPECT_EQ(lines_of(v.out), std::vector<std::string>{"verify: 3 jobs, 0 problems"});

    const std::string png = out("folder") + "/sphere/toon/az090_el20.png";
    const std::string exr = out("folder") + "/sphere/toon/az180_el20.depth.exr";
    fs::remove(png);
    fs::resize_file(exr, fs::file_size(exr) - 100);
    v = run_cli("batch " + manifest + " --verify " + out("folder") + common);
    EXPECT_EQ(v.status, 1);
    const std::vector<std::string> problems = lines_of(v.out);
    ASSERT_EQ(problems.size(), 3u) << v.out;
    EXPECT_EQ(problems[0], png + ": missing");
    EXPECT_TRUE(problems[1].starts_with(exr + ": truncated OpenEXR file")) << problems[1];
    EXPECT_EQ(problems[2], "verify: 3 jobs, 2 problems");
    // Other options make other jobs: every metadata's hash is stale.
    v = run_cli("batch " + manifest + " --verify " + out("folder") + " --size 40x40 -q");
    EXPECT_EQ(v.status, 1);
    EXPECT_NE(v.out.find("rendered with other options"), std::string::npos) << v.out;

    const std::string wds = " --layout webdataset --shard-size 1kB";  // one sample a shard
    ASSERT_EQ(run_cli("batch " + manifest + " -o " + out("wds") + common + wds).status, 0);
    v = run_cli("batch " + manifest + " --verify " + out("wds") + common + wds);
    EXPECT_EQ(v.status, 0) << v.out << v.err;
    const std::vector<std::string> shards = shards_in(out("wds"));
    ASSERT_EQ(shards.size(), 3u);
    fs::resize_file(shards[1], fs::file_size(shards[1]) - 2000);
    fs::remove(shards[2]);
    v = run_cli("batch " + manifest + " --verify " + out("wds") + common + wds);
    EXPECT_EQ(v.status, 1);
    const std::vector<std::string> wds_problems = lines_of(v.out);
    ASSERT_GE(wds_problems.size(), 3u) << v.out;
    EXPECT_TRUE(wds_problems[0].starts_with(shards[1] + ": truncated")) << v.out;
    EXPECT_NE(v.out.find("sphere/toon/az180_el20: missing (no sample sphere/toon/az180_el20 in the shards)"),
              std::string::npos)
        << v.out;
}

TEST_F(WebDatasetBatch, BadLayoutOptionsAreExit2WithOneLine) {
    const std::string manifest = dir_.write("jobs.csv", "model\nbuiltin:sphere\n");
    for (const char* size : {"0", "-1", "1XB", "abc", "''", "1e30GB", "0.1"}) {
        const CliResult r =
            run_cli("batch " + manifest + " -o " + out() + " --layout webdataset --shard-size " + std::string(size));
        EXPECT_EQ(r.status, 2) << size;
        EXPECT_EQ(line_count(r.err), 1) << r.err;
        EXPECT_NE(r.err.find("--shard-size"), std::string::npos) << r.err;
    }
    CliResult r = run_cli("batch " + manifest + " -o " + out() + " --shard-size 1GB");  // folder layout
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--shard-size: only with --layout webdataset"), std::string::npos) << r.err;
    r = run_cli("batch " + manifest + " -o " + out() + " --layout tar");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(out())) << "nothing is written for bad options";
    // Two stems that differ only where the key has '_' for '.'.
    const std::string clash =
        dir_.write("clash.csv", "model,views\nbuiltin:sphere,\"22.5:30;eye=0,0,5 name=az022_5_el30\"\n");
    r = run_cli("batch " + clash + " -o " + out() + " --layout webdataset");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("WebDataset key 'sphere/lambert/az022_5_el30'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace inkshade::test
