// `render --aov` and `batch` AOVs as files: the acceptance reprojection of a sphere's depth
// through OUT.camera.json, ids of two objects in 16-bit PNGs, bad names, per-job batch AOVs.
#include <gtest/gtest.h>

#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "cli/exr_channel.hpp"
#include "cli/json_matrix.hpp"
#include "cli/run_cli.hpp"
#include "inkshade/image.hpp"

namespace inkshade::test {
namespace {

namespace fs = std::filesystem;

// The EXR's depth channel Z, top row first.
std::vector<float> read_depth(const std::string& path, int& width, int& height) {
    return read_exr_channel(path, "Z", width, height);
}

// The acceptance test: the depth AOV of a sphere, turned into 3-D points with nothing but the
// camera file (docs/aov.md's recipe), lies on a sphere of the model's radius within 0.5 %.
TEST(AovCli, SphereDepthReprojectsThroughTheCameraFile) {
    for (const char* projection : {"", " --ortho"}) {
        SCOPED_TRACE(projection);
        TempDir dir;
        const std::string out = dir.file("s.png");
        auto r = run_cli(
            "render builtin:sphere:rings=128,segments=256 --size 320x240 --azimuth 30 --elevation 25 "
            "--aov depth,normal,id,material,mask,lines --style anime -o " +
            out + projection);
        ASSERT_EQ(r.status, 0) << r.err;
        for (const char* name :
             {"s.png", "s.depth.exr", "s.normal.png", "s.id.png", "s.material.png", "s.mask.png", "s.lines-hull.png",
              "s.lines-rim-contour.png", "s.lines-suggestive-image.png", "s.camera.json"})
            EXPECT_TRUE(fs::is_regular_file(dir.file(name))) << name;
        const nlohmann::json cam = nlohmann::json::parse(slurp(dir.file("s.camera.json")));
        int w = 0, h = 0;
        const std::vector<float> depth = read_depth(dir.file("s.depth.exr"), w, h);
        ASSERT_EQ(w, cam["image"]["width"].get<int>());
        ASSERT_EQ(h, cam["image"]["height"].get<int>());
        const bool ortho = cam["projection"] == "orthographic";
        EXPECT_EQ(ortho, std::string(projection) == " --ortho");
        const double fx = cam["K"][0][0], fy = cam["K"][1][1], cx = cam["K"][0][2], cy = cam["K"][1][2];
        const glm::dmat4 camera_to_world = glm::inverse(matrix(cam["world_to_camera_opencv"]));
        const glm::dvec3 lo(cam["model_bounds"]["min"][0], cam["model_bounds"]["min"][1],
                            cam["model_bounds"]["min"][2]);
        const glm::dvec3 hi(cam["model_bounds"]["max"][0], cam["model_bounds"]["max"][1],
                            cam["model_bounds"]["max"][2]);
        const glm::dvec3 centre = 0.5 * (lo + hi);
        const double radius = 0.5 * (hi.x - lo.x);
        double sum = 0.0;
        int n = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double d = depth[size_t(y * w + x)];
                if (d == 0.0) continue;  // background
                const double u = x + 0.5, v = y + 0.5;
                const double s = ortho ? 1.0 : d;  // pinhole: x = (u - cx) d / fx; orthographic: (u - cx) / fx
                const glm::dvec4 p = camera_to_world * glm::dvec4((u - cx) * s / fx, (v - cy) * s / fy, d, 1.0);
                sum += glm::length(glm::dvec3(p) - centre);
                ++n;
            }
        ASSERT_GT(n, 10000);
        EXPECT_NEAR(sum / n / radius, 1.0, 0.005);
    }
}

// Two cubes of two materials: ids 1 and 2, materials 1 and 2, 0 on the background, in 16-bit
// gray PNGs.
TEST(AovCli, IdsAndMaterialsOfTwoObjects) {
    TempDir dir;
    std::string obj = "mtllib two.mtl\n";
    for (int cube = 0; cube < 2; ++cube) {
        const float cx = cube == 0 ? -2.0f : 2.0f;
        for (int i = 0; i < 8; ++i)
            obj += "v " + std::to_string(cx + ((i & 1) ? 0.5f : -0.5f)) + " " + ((i & 2) ? "0.5" : "-0.5") + " " +
                   ((i & 4) ? "0.5" : "-0.5") + "\n";
    }
    const char* faces[] = {"1 2 4 3", "5 7 8 6", "1 5 6 2", "3 4 8 7", "1 3 7 5", "2 6 8 4"};
    for (int cube = 0; cube < 2; ++cube) {
        obj += std::string("usemtl ") + (cube == 0 ? "red" : "blue") + "\n";
        for (const char* f : faces) {
            obj += "f";
            int a, b, c, d;
            std::sscanf(f, "%d %d %d %d", &a, &b, &c, &d);
            for (int k : {a, b, c, d}) obj += " " + std::to_string(k + 8 * cube);
            obj += "\n";
        }
    }
    dir.write("two.obj", obj);
    dir.write("two.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
    const std::string out = dir.file("t.png");
    auto r = run_cli("render " + dir.file("two.obj") +
                     " --size 200x100 --ortho --ortho-height 4 --eye 0,0,5 --target 0,0,0 --aov id,material -o " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    const Image id = read_png(dir.file("t.id.png")), material = read_png(dir.file("t.material.png"));
    ASSERT_EQ(id.rgba16.size(), size_t(200 * 100 * 4));  // 16 bits
    auto at = [](const Image& img, int x, int y) { return img.rgba16[(size_t(y) * img.width + x) * 4]; };
    // 25 pixels a unit: the cubes' centres at x = 50 and 150.
    EXPECT_EQ(at(id, 50, 50), 1);
    EXPECT_EQ(at(id, 150, 50), 2);
    EXPECT_EQ(at(id, 100, 50), 0);
    EXPECT_EQ(at(material, 50, 50), 1);
    EXPECT_EQ(at(material, 150, 50), 2);
    EXPECT_EQ(at(material, 100, 50), 0);
    EXPECT_FALSE(fs::exists(dir.file("t.depth.exr")));  // only what was asked, and the camera
    EXPECT_TRUE(fs::exists(dir.file("t.camera.json")));
}

TEST(AovCli, UnknownAovIsOneLineExitTwoAndNoFile) {
    TempDir dir;
    auto r = run_cli("render builtin:sphere --size 32x32 --aov depth,nromal -o " + dir.file("a.png"));
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err,
              "inkshade: --aov: unknown AOV 'nromal' (expected depth, normal, id, material, mask, lines, lineset-ids, "
              "ndotv, kr, dwkr, k1, k2, pdir1, pdir2, shading-scales, camera) (did you mean 'normal'?)\n");
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

// Per-job AOVs: the manifest's aov column, else --aov; the same bytes as `render --aov`.
TEST(AovCli, BatchWritesEachJobsAovs) {
    TempDir dir;
    const std::string manifest = dir.write("jobs.csv",
                                           "model,name,styles,size,aov\n"
                                           "builtin:sphere,a,lambert,64x48,\"depth,mask\"\n"
                                           "builtin:torus,b,anime,64x48,\n");
    const std::string out = dir.file("ds");
    auto r = run_cli("batch " + manifest + " -o " + out + " --aov normal -q");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string a = out + "/a/lambert/az035_el20", b = out + "/b/anime/az035_el20";
    for (const std::string& f :
         {a + ".depth.exr", a + ".mask.png", a + ".camera.json", b + ".normal.png", b + ".camera.json"})
        EXPECT_TRUE(fs::is_regular_file(f)) << f;
    EXPECT_FALSE(fs::exists(a + ".normal.png"));
    EXPECT_FALSE(fs::exists(b + ".depth.exr"));
    const nlohmann::json meta = nlohmann::json::parse(slurp(a + ".json"));
    EXPECT_EQ(meta["outputs"]["aov"],
              nlohmann::json::array({"az035_el20.depth.exr", "az035_el20.mask.png", "az035_el20.camera.json"}));
    EXPECT_EQ(meta["aov"], "depth,mask");

    // `render` with the job's options writes the same bytes.
    auto single =
        run_cli("render builtin:sphere --style lambert --size 64x48 --aov depth,mask -o " + dir.file("r.png"));
    ASSERT_EQ(single.status, 0) << single.err;
    EXPECT_EQ(slurp(dir.file("r.depth.exr")), slurp(a + ".depth.exr"));
    EXPECT_EQ(slurp(dir.file("r.mask.png")), slurp(a + ".mask.png"));
    EXPECT_EQ(slurp(dir.file("r.png")), slurp(a + ".png"));

    // Resume: complete jobs skip; a missing AOV file renders its job again.
    auto again = run_cli("batch " + manifest + " -o " + out + " --aov normal -q");
    EXPECT_NE(again.out.find("0 done, 2 skipped"), std::string::npos) << again.out;
    fs::remove(a + ".mask.png");
    again = run_cli("batch " + manifest + " -o " + out + " --aov normal -q");
    EXPECT_NE(again.out.find("1 done, 1 skipped"), std::string::npos) << again.out;
    EXPECT_TRUE(fs::is_regular_file(a + ".mask.png"));

    // A bad name in the manifest: exit 2 naming the line.
    const std::string bad = dir.write("bad.csv", "model,aov\nbuiltin:sphere,\"depth,lnies\"\n");
    auto b2 = run_cli("batch " + bad + " -o " + out);
    EXPECT_EQ(b2.status, 2);
    EXPECT_NE(b2.err.find("bad.csv:2: aov: unknown AOV 'lnies'"), std::string::npos) << b2.err;
    EXPECT_NE(b2.err.find("(did you mean 'lines'?)"), std::string::npos) << b2.err;
}

}  // namespace
}  // namespace inkshade::test

namespace inkshade::test {
namespace {

// `--lineset-ids`: one mask per line set beside the image, named after it, listed as the render
// prints its outputs; each line set's own type masks with `--aov lines`.
TEST(AovCli, LineSetIdsWriteOneMaskPerSet) {
    TempDir dir;
    const std::string style = dir.write("sets.toml",
                                        "[shading]\nmodel = \"lambert\"\n[[lines]]\ntype = \"hull\"\n"
                                        "[[lineset]]\nname = \"plate\"\nobjects = \"Plate\"\n"
                                        "[[lineset.lines]]\ntype = \"crease\"\n"
                                        "[[lineset]]\nname = \"bolts\"\nobjects = \"Bolt.*\"\n"
                                        "[[lineset.lines]]\ntype = \"crease\"\n");
    const std::string out = dir.file("p.png");
    auto r = run_cli("render " + std::string(INKSHADE_SOURCE_DIR) + "/examples/cad-part/part.obj --style " + style +
                     " --size 160x120 --lineset-ids --aov lines -o " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* name : {"p.lineset-default.png", "p.lineset-plate.png", "p.lineset-bolts.png", "p.lines-hull.png",
                             "p.lines-plate-crease.png", "p.lines-bolts-crease.png"})
        EXPECT_TRUE(fs::is_regular_file(dir.file(name))) << name;
    EXPECT_FALSE(fs::exists(dir.file("p.lineset-shaft.png")));
}

}  // namespace
}  // namespace inkshade::test
