// run_batch as a library call (what the Python binding uses): progress events, the stop flag,
// resume, a model that fails to load.
#include <gtest/gtest.h>

#include <filesystem>

#include "inkshade/batch.hpp"
#include "support/temp_dir.hpp"

namespace inkshade {
namespace {

std::vector<BatchJob> jobs_for(const std::vector<std::string>& models, const std::string& views) {
    std::vector<BatchModel> list;
    for (const std::string& m : models) list.push_back({m, model_name(m)});
    BatchDefaults d;
    d.views = views;
    d.styles = "lambert";
    d.options.size = {32, 32};
    return expand_jobs(list, d);
}

size_t metadata_files(const std::filesystem::path& dir) {
    size_t n = 0;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) n += e.path().extension() == ".json";
    return n;
}

TEST(BatchRunner, ReportsEveryJobInOrderThenSkipsThemOnResume) {
    test::TempDir dir;
    BatchOptions options;
    options.output_dir = dir.file("out");
    const auto jobs = jobs_for({"builtin:sphere:rings=8,segments=16"}, "turntable:4");
    std::vector<BatchEvent> events;
    std::vector<std::string> stems;  // event.job lives as long as the callback only
    BatchSummary s = run_batch(jobs, options, [&](const BatchEvent& e) {
        events.push_back(e);
        stems.push_back(e.job->stem);
    });
    EXPECT_EQ(s.total, 4u);
    EXPECT_EQ(s.done, 4u);
    EXPECT_FALSE(s.interrupted);
    ASSERT_EQ(events.size(), 4u);
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(events[i].status, BatchStatus::Done);
        EXPECT_EQ(events[i].finished, i + 1);
        EXPECT_EQ(events[i].rendered, i + 1);
        EXPECT_EQ(events[i].to_render, 4u);
        EXPECT_EQ(stems[i], jobs[i].stem);
    }
    EXPECT_EQ(metadata_files(options.output_dir), 4u);

    events.clear();
    s = run_batch(jobs, options, [&](const BatchEvent& e) { events.push_back(e); });
    EXPECT_EQ(s.skipped, 4u);
    EXPECT_EQ(s.done, 0u);
    ASSERT_EQ(events.size(), 4u);
    EXPECT_EQ(events[0].status, BatchStatus::Skipped);
    EXPECT_EQ(events[0].to_render, 0u);
}

TEST(BatchRunner, StopFlagEndsTheBatchAfterTheJobInProgress) {
    test::TempDir dir;
    std::atomic<bool> stop{false};
    BatchOptions options;
    options.output_dir = dir.file("out");
    options.stop = &stop;
    const auto jobs = jobs_for({"builtin:sphere:rings=8,segments=16", "builtin:torus"}, "turntable:5");
    const BatchSummary s = run_batch(jobs, options, [&](const BatchEvent& e) {
        if (e.finished == 2) stop = true;  // as a signal handler would, mid-batch
    });
    // Job 2's event comes once job 3 is rendered (its files are written meanwhile): job 3 was
    // in progress, so it completes, and nothing after it starts.
    EXPECT_TRUE(s.interrupted);
    EXPECT_EQ(s.total, 10u);
    EXPECT_EQ(s.done, 3u);
    EXPECT_EQ(metadata_files(options.output_dir), 3u);
}

TEST(BatchRunner, ModelThatFailsToLoadIsOneEventAndTheRestRenders) {
    test::TempDir dir;
    BatchOptions options;
    options.output_dir = dir.file("out");
    const auto jobs = jobs_for({dir.file("absent.obj"), "builtin:sphere:rings=8,segments=16"}, "0:0,90:0,180:0");
    std::vector<BatchEvent> failures;
    const BatchSummary s = run_batch(jobs, options, [&](const BatchEvent& e) {
        if (e.status == BatchStatus::Failed) failures.push_back(e);
    });
    EXPECT_EQ(s.failed, 3u);
    EXPECT_EQ(s.done, 3u);
    ASSERT_EQ(s.failures.size(), 3u);
    ASSERT_EQ(failures.size(), 1u);
    EXPECT_TRUE(failures[0].model_failed);
    EXPECT_EQ(failures[0].jobs, 3u);
    EXPECT_NE(failures[0].reason.find(dir.file("absent.obj")), std::string::npos) << failures[0].reason;
}

}  // namespace
}  // namespace inkshade
