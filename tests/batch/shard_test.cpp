// Batch job order, shards and job hashes: shards partition the job list, keep models
// together, and the hash changes exactly with what decides a job's files.
#include <gtest/gtest.h>

#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"

namespace inkshade {
namespace {

std::vector<BatchJob> jobs_for(int models, const std::string& views, const std::string& styles) {
    std::vector<BatchModel> list;
    // Listed out of path order: batch_order sorts by model.
    for (int m = models - 1; m >= 0; --m) list.push_back({"m" + std::to_string(m) + ".obj", "m" + std::to_string(m)});
    BatchDefaults d;
    d.views = views;
    d.styles = styles;
    return expand_jobs(list, d);
}

std::vector<std::string> stems(const std::vector<BatchJob>& jobs) {
    std::vector<std::string> s;
    for (const BatchJob& j : jobs) s.push_back(j.stem);
    return s;
}

TEST(BatchShard, OrderGroupsModelsAndKeepsTheirJobOrder) {
    const auto ordered = batch_order(jobs_for(3, "0:0,90:0", "toon,anime"));
    EXPECT_EQ(stems(ordered),
              (std::vector<std::string>{"m0/toon/az000_el00", "m0/toon/az090_el00", "m0/anime/az000_el00",
                                        "m0/anime/az090_el00", "m1/toon/az000_el00", "m1/toon/az090_el00",
                                        "m1/anime/az000_el00", "m1/anime/az090_el00", "m2/toon/az000_el00",
                                        "m2/toon/az090_el00", "m2/anime/az000_el00", "m2/anime/az090_el00"}));
}

TEST(BatchShard, ShardsPartitionTheOrderedListInContiguousBlocks) {
    for (int models : {1, 2, 3, 7}) {
        for (const std::string views : {"0:0", "turntable:5", "orbit4x3"}) {
            const auto all = stems(batch_order(jobs_for(models, views, "toon,anime")));
            for (int n = 1; n <= 9; ++n) {
                std::vector<std::string> joined;
                size_t smallest = all.size(), largest = 0;
                for (int k = 1; k <= n; ++k) {
                    const auto part = stems(shard(jobs_for(models, views, "toon,anime"), k, n));
                    joined.insert(joined.end(), part.begin(), part.end());
                    smallest = std::min(smallest, part.size());
                    largest = std::max(largest, part.size());
                }
                EXPECT_EQ(joined, all) << models << " models, " << views << ", " << n << " shards";
                EXPECT_LE(largest - smallest, 1u);
            }
        }
    }
}

TEST(BatchShard, ThreeShardsOfTwentyFourJobs) {
    const auto jobs = jobs_for(3, "0:0,90:0,180:0,270:0", "toon,anime");
    ASSERT_EQ(jobs.size(), 24u);
    // Contiguous: shard 1 is model m0's 8 jobs, and so on; each shard loads one model.
    for (int k = 1; k <= 3; ++k) {
        const auto part = shard(jobs, k, 3);
        ASSERT_EQ(part.size(), 8u);
        for (const BatchJob& j : part) EXPECT_EQ(j.model, "m" + std::to_string(k - 1) + ".obj");
    }
    // More shards than jobs: some are empty.
    EXPECT_TRUE(shard(jobs_for(1, "0:0", "toon"), 1, 2).empty());
    EXPECT_EQ(shard(jobs_for(1, "0:0", "toon"), 2, 2).size(), 1u);
}

TEST(BatchShard, BadShardArgumentsAreInputErrors) {
    int k = 0, n = 0;
    parse_shard("2/3", k, n);
    EXPECT_EQ(k, 2);
    EXPECT_EQ(n, 3);
    for (const std::string bad : {"", "3", "/3", "2/", "0/3", "4/3", "-1/3", "1/0", "a/b", "1/3/5", "1.5/3", " 1/3"})
        EXPECT_THROW(parse_shard(bad, k, n), InputError) << bad;
    const auto jobs = jobs_for(1, "0:0", "toon");
    EXPECT_THROW(shard(jobs, 0, 3), InputError);
    EXPECT_THROW(shard(jobs, 4, 3), InputError);
    EXPECT_THROW(shard(jobs, 1, 0), InputError);
}

TEST(BatchShard, JobHashFollowsEverythingThatDecidesTheFiles) {
    const BatchJob job = jobs_for(1, "30:20", "toon")[0];
    const std::string h = job_hash(job, "style text", 1234);
    EXPECT_EQ(h.size(), 16u);
    EXPECT_EQ(h.find_first_not_of("0123456789abcdef"), std::string::npos);
    EXPECT_EQ(job_hash(job, "style text", 1234), h);  // deterministic
    EXPECT_NE(job_hash(job, "style text edited", 1234), h);
    EXPECT_NE(job_hash(job, "style text", 1235), h);
    auto changed = [&](auto edit) {
        BatchJob j = job;
        edit(j);
        return job_hash(j, "style text", 1234);
    };
    EXPECT_NE(changed([](BatchJob& j) { j.options.samples = 1; }), h);
    EXPECT_NE(changed([](BatchJob& j) { j.options.size.x = 256; }), h);
    EXPECT_NE(changed([](BatchJob& j) { j.outputs.svg = true; }), h);
    EXPECT_NE(changed([](BatchJob& j) { j.view.camera.azimuth_degrees = 31.0f; }), h);
    EXPECT_NE(changed([](BatchJob& j) { j.options.camera.fov_degrees = 40.0f; }), h);
    EXPECT_NE(changed([](BatchJob& j) { j.options.camera.margin = 0.1f; }), h);
    EXPECT_NE(changed([](BatchJob& j) { j.view.camera.eye = glm::vec3(1.0f); }), h);
    EXPECT_NE(changed([](BatchJob& j) { j.model = "other.obj"; }), h);
    EXPECT_NE(changed([](BatchJob& j) { j.style = "anime"; }), h);
    // Where the job came from is not part of it.
    EXPECT_EQ(changed([](BatchJob& j) { j.source = "elsewhere.csv:9"; }), h);
}

}  // namespace
}  // namespace inkshade
