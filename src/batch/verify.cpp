// verify_batch (inkshade/batch.hpp): a batch's output checked against its jobs, in either layout,
// one line per problem.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include "batch/job_outputs.hpp"
#include "batch/job_style.hpp"
#include "batch/metadata.hpp"
#include "batch/output_check.hpp"
#include "batch/webdataset_shards.hpp"
#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"
#include "io/tar_reader.hpp"

namespace inkshade {

namespace {

namespace fs = std::filesystem;
using Problems = std::vector<std::string>;

std::optional<std::string> read_file(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

// The metadata's hash and outputs: false (with the problem) when they cannot be used.
bool check_metadata(const std::string& where, const std::string& text, const std::string& hash,
                    std::vector<std::string>& outputs, Problems& problems) {
    if (const std::string p = batch::output_problem(".json", text); !p.empty()) {
        problems.push_back(where + ": " + p);
        return false;
    }
    if (const std::string h = batch::metadata_job_hash(text); h != hash)
        problems.push_back(where + ": job hash " + (h.empty() ? "missing" : h) + ", the job's is " + hash +
                           " (rendered with other options)");
    try {
        outputs = batch::job_output_names(text);
    } catch (const RuntimeError& e) {
        problems.push_back(where + ": " + e.what());
        return false;
    }
    return true;
}

void verify_folder_job(const std::string& dir, const BatchJob& job, const std::string& hash, Problems& problems) {
    const fs::path metadata = batch::job_file(dir, job, ".json");
    const std::optional<std::string> text = read_file(metadata);
    if (!text) return problems.push_back(metadata.string() + ": missing");
    std::vector<std::string> outputs;
    if (!check_metadata(metadata.string(), *text, hash, outputs, problems)) return;
    for (const std::string& name : outputs) {
        const fs::path file = metadata.parent_path() / name;
        const std::optional<std::string> bytes = read_file(file);
        if (!bytes) {
            problems.push_back(file.string() + ": missing");
        } else if (const std::string p = batch::output_problem(name, *bytes); !p.empty()) {
            problems.push_back(file.string() + ": " + p);
        }
    }
}

struct Sample {
    std::string shard;
    std::set<std::string> members;  // extensions: ".png", ".depth.exr", ".json", ...
    std::optional<std::string> metadata;
};

// Every sample of the prefix's shards, each member checked as it is read.
std::map<std::string, Sample> read_shards(const BatchOptions& options, Problems& problems) {
    const std::regex shard_name(
        std::regex_replace(options.shard_prefix, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") + R"(-\d{6}\.tar)");
    std::vector<fs::path> shards;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(options.output_dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (std::regex_match(name, shard_name)) shards.push_back(entry.path());
        if (name.starts_with("." + options.shard_prefix + "-") && name.find(".tar.tmp-") != std::string::npos)
            problems.push_back(entry.path().string() + ": temporary of an unfinished shard (run the batch again)");
    }
    std::sort(shards.begin(), shards.end());
    if (shards.empty()) problems.push_back(options.output_dir + ": no shards " + options.shard_prefix + "-NNNNNN.tar");
    std::map<std::string, Sample> samples;
    for (const fs::path& shard : shards) {
        std::string previous;
        try {
            io::TarReader reader(shard.string());
            while (const auto m = reader.next()) {
                const std::string key = batch::member_key(m->name), where = shard.string() + ": " + m->name;
                auto [it, fresh] = samples.try_emplace(key, Sample{shard.string(), {}, {}});
                if (!fresh && (key != previous || it->second.shard != shard.string()))
                    problems.push_back(where + ": sample " + key + " also in " + it->second.shard);
                previous = key;
                const std::string bytes = reader.read(*m);
                if (const std::string p = batch::output_problem(m->name, bytes); !p.empty())
                    problems.push_back(where + ": " + p);
                it->second.members.insert(m->name.substr(key.size()));
                if (m->name == key + ".json") it->second.metadata = bytes;
            }
        } catch (const RuntimeError& e) {
            problems.push_back(e.what());
        }
    }
    return samples;
}

void verify_shards(const std::vector<BatchJob>& jobs, const std::vector<std::string>& hashes,
                   const BatchOptions& options, Problems& problems) {
    std::map<std::string, Sample> samples = read_shards(options, problems);
    for (size_t i = 0; i < jobs.size(); ++i) {
        const std::string key = webdataset_key(jobs[i].stem);
        const auto it = samples.find(key);
        if (it == samples.end()) {
            problems.push_back(jobs[i].stem + ": missing (no sample " + key + " in the shards)");
            continue;
        }
        const Sample sample = std::move(it->second);
        samples.erase(it);
        const std::string where = sample.shard + ": " + key;
        if (!sample.metadata) {
            problems.push_back(where + ".json: missing");
            continue;
        }
        std::vector<std::string> outputs;
        if (hashes[i].empty() || !check_metadata(where + ".json", *sample.metadata, hashes[i], outputs, problems))
            continue;
        const std::string base = fs::path(jobs[i].stem).filename().string();
        for (const std::string& name : outputs) {
            const std::string extension = name.starts_with(base) ? name.substr(base.size()) : "/" + name;
            if (!sample.members.count(extension)) problems.push_back(where + extension + ": missing");
        }
    }
    for (const auto& [key, sample] : samples)
        problems.push_back(sample.shard + ": " + key + ": not a job of this manifest");
}

}  // namespace

std::vector<std::string> verify_batch(const std::vector<BatchJob>& jobs, const BatchOptions& options) {
    Problems problems;
    std::map<std::string, batch::ResolvedStyle> styles;
    std::vector<std::string> hashes;
    for (const BatchJob& job : jobs) {
        auto it = styles.find(job.style);
        if (it == styles.end()) it = styles.emplace(job.style, batch::resolve_style(job.style)).first;
        if (!it->second.error.empty()) problems.push_back(job.stem + ": " + it->second.error);
        hashes.push_back(it->second.error.empty() ? job_hash(job, it->second.toml, batch::model_bytes(job.model)) : "");
    }
    if (options.layout == BatchLayout::WebDataset) {
        verify_shards(jobs, hashes, options, problems);
    } else {
        for (size_t i = 0; i < jobs.size(); ++i)
            if (!hashes[i].empty()) verify_folder_job(options.output_dir, jobs[i], hashes[i], problems);
    }
    return problems;
}

}  // namespace inkshade
