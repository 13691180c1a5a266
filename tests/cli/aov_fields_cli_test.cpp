// The surface-field AOVs as files: `render --aov` writes one float EXR per field, read back
// with OpenEXR, whose p90 factors recomputed from the EXR are the camera file's; `batch`
// writes the same files and the factors into the job's metadata (docs/aov.md).
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/exr_channel.hpp"
#include "cli/run_cli.hpp"

namespace inkshade::test {
namespace {

namespace fs = std::filesystem;

// numpy.percentile(|v|, 90) over the pixels where depth > 0.
double p90(const std::vector<float>& v, const std::vector<float>& depth) {
    std::vector<double> a;
    for (size_t i = 0; i < v.size(); ++i)
        if (depth[i] > 0.0f) a.push_back(std::abs(double(v[i])));
    std::sort(a.begin(), a.end());
    const double rank = 0.9 * double(a.size() - 1);
    const size_t lo = size_t(rank), hi = std::min(lo + 1, a.size() - 1);
    return a[lo] + (rank - double(lo)) * (a[hi] - a[lo]);
}

TEST(AovFieldsCli, ExrFieldsAndTheirFactorsInTheCameraFile) {
    TempDir dir;
    const std::string out = dir.file("t.png");
    auto r = run_cli(
        "render builtin:torus --size 160x120 --azimuth 30 --elevation 40 "
        "--aov depth,ndotv,kr,dwkr,k1,k2,pdir1,pdir2,shading-scales -o " +
        out);
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* name : {"t.ndotv.exr", "t.kr.exr", "t.dwkr.exr", "t.k1.exr", "t.k2.exr", "t.pdir1.exr",
                             "t.pdir2.exr", "t.shading-s0.png", "t.shading-s4.png"})
        EXPECT_TRUE(fs::is_regular_file(dir.file(name))) << name;
    int w = 0, h = 0;
    const std::vector<float> depth = read_exr_channel(dir.file("t.depth.exr"), "Z", w, h);
    ASSERT_EQ(depth.size(), size_t(160 * 120));
    const nlohmann::json cam = nlohmann::json::parse(slurp(dir.file("t.camera.json")));
    ASSERT_TRUE(cam.contains("fields")) << cam.dump();
    EXPECT_GT(cam["fields"]["feature_size"].get<double>(), 0.0);
    EXPECT_EQ(cam["fields"]["shading_sigmas"].size(), 5u);
    for (const char* name : {"kr", "dwkr", "k1", "k2"}) {
        SCOPED_TRACE(name);
        const std::vector<float> v = read_exr_channel(dir.file(std::string("t.") + name + ".exr"), "Y", w, h);
        ASSERT_EQ(v.size(), depth.size());
        const double want = p90(v, depth);
        EXPECT_GT(want, 0.0);
        EXPECT_NEAR(cam["fields"]["p90"][name].get<double>(), want, 1e-6 * want);
    }
    // Values on the visible surface only; pdir as unit X, Y.
    const std::vector<float> ndotv = read_exr_channel(dir.file("t.ndotv.exr"), "Y", w, h);
    const std::vector<float> px = read_exr_channel(dir.file("t.pdir1.exr"), "X", w, h);
    const std::vector<float> py = read_exr_channel(dir.file("t.pdir1.exr"), "Y", w, h);
    ASSERT_EQ(px.size(), depth.size());
    for (size_t i = 0; i < depth.size(); ++i) {
        if (depth[i] == 0.0f) {
            EXPECT_EQ(ndotv[i], 0.0f);
            EXPECT_EQ(px[i], 0.0f);
            continue;
        }
        EXPECT_LE(std::abs(ndotv[i]), 1.0f);
        EXPECT_NEAR(std::hypot(px[i], py[i]), 1.0, 1e-4);
    }
}

TEST(AovFieldsCli, BatchWritesTheFactorsIntoTheMetadata) {
    TempDir dir;
    const std::string manifest = dir.write("jobs.csv",
                                           "model,name,styles,size,aov\n"
                                           "builtin:sphere,a,lambert,64x48,\"kr,ndotv\"\n");
    const std::string out = dir.file("ds");
    auto r = run_cli("batch " + manifest + " -o " + out + " -q");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string a = out + "/a/lambert/az035_el20";
    const nlohmann::json meta = nlohmann::json::parse(slurp(a + ".json"));
    EXPECT_EQ(meta["outputs"]["aov"],
              nlohmann::json::array({"az035_el20.ndotv.exr", "az035_el20.kr.exr", "az035_el20.camera.json"}));
    const nlohmann::json cam = nlohmann::json::parse(slurp(a + ".camera.json"));
    EXPECT_EQ(meta["fields"], cam["fields"]);
    EXPECT_TRUE(meta["fields"]["p90"].contains("kr"));
}

}  // namespace
}  // namespace inkshade::test
