// A batch's transforms.json (instant-ngp / nerfstudio layout) against the camera files of the
// same jobs, and export-mesh's mesh against the model's world positions.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "inkshade/batch.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/mesh_writer.hpp"
#include "support/temp_dir.hpp"

namespace inkshade {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json read_json(const fs::path& path) {
    std::ifstream in(path);
    return json::parse(in);
}

glm::dmat4 matrix(const json& rows) {
    glm::dmat4 m(1.0);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = rows.at(r).at(c).get<double>();
    return m;
}

std::vector<BatchJob> jobs_for(const std::string& model, const std::string& views, glm::ivec2 size) {
    BatchDefaults d;
    d.views = views;
    d.styles = "lambert";
    d.options.size = size;
    d.options.aovs = {"camera"};
    return expand_jobs({{model, model_name(model)}}, d);
}

// Each frame's transform_matrix is the inverse of its camera file's world_to_camera, and the
// intrinsics are the camera file's K.
void expect_frames_match_camera_files(const fs::path& dir, const json& t, bool shared) {
    for (const json& frame : t.at("frames")) {
        const std::string image = frame.at("file_path");
        SCOPED_TRACE(image);
        const std::string stem = image.substr(0, image.size() - 4);
        const json cam = read_json(dir / (stem + ".camera.json"));
        const glm::dmat4 product = matrix(frame.at("transform_matrix")) * matrix(cam.at("world_to_camera"));
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(product[c][r], c == r ? 1.0 : 0.0, 1e-6);
        const json& k = shared ? t : frame;
        EXPECT_NEAR(k.at("fl_x").get<double>(), cam["K"][0][0].get<double>(), 1e-9);
        EXPECT_NEAR(k.at("fl_y").get<double>(), cam["K"][1][1].get<double>(), 1e-9);
        EXPECT_NEAR(k.at("cx").get<double>(), cam["K"][0][2].get<double>(), 1e-9);
        EXPECT_NEAR(k.at("cy").get<double>(), cam["K"][1][2].get<double>(), 1e-9);
        EXPECT_EQ(k.at("w").get<int>(), cam["image"]["width"].get<int>());
        EXPECT_EQ(k.at("h").get<int>(), cam["image"]["height"].get<int>());
        if (!k.contains("orthographic")) {
            EXPECT_NEAR(k.at("camera_angle_x").get<double>(), glm::radians(cam.at("fov_x_degrees").get<double>()),
                        1e-9);
        }
    }
}

TEST(TransformsJson, FramesAreTheCameraFilesInverses) {
    test::TempDir dir;
    BatchOptions options;
    options.output_dir = dir.file("out");
    options.transforms_json = true;
    const auto jobs = jobs_for("builtin:torus", "fibonacci:3;eye=1,2,3 up=0,0,1 name=side", {48, 32});
    ASSERT_EQ(run_batch(jobs, options).done, 4u);
    const fs::path scene = fs::path(options.output_dir) / "torus" / "lambert";
    const json t = read_json(scene / "transforms.json");
    ASSERT_EQ(t.at("frames").size(), 4u);
    EXPECT_EQ(t["frames"][0]["file_path"], "fib3_000.png");
    EXPECT_EQ(t["w"], 48);
    EXPECT_EQ(t["h"], 32);
    EXPECT_EQ(t["camera_model"], "OPENCV");
    EXPECT_NEAR(t["camera_angle_y"].get<double>(), glm::radians(30.0), 1e-9);  // the default --fov
    expect_frames_match_camera_files(scene, t, /*shared=*/true);

    // Resume: a run with every job complete writes the same file, listing every job.
    const std::string before = t.dump();
    fs::remove(scene / "transforms.json");
    ASSERT_EQ(run_batch(jobs, options).skipped, 4u);
    EXPECT_EQ(read_json(scene / "transforms.json").dump(), before);
}

TEST(TransformsJson, MixedProjectionsAndSizesGoPerFrame) {
    test::TempDir dir;
    BatchOptions options;
    options.output_dir = dir.file("out");
    options.transforms_json = true;
    auto jobs = jobs_for("builtin:sphere:rings=8,segments=16", "ico:0", {40, 40});
    jobs.resize(2);
    jobs[1].options.camera.orthographic = true;
    jobs[1].options.size = {30, 20};
    ASSERT_EQ(run_batch(jobs, options).done, 2u);
    const fs::path scene = fs::path(options.output_dir) / jobs[0].stem;
    const json t = read_json(scene.parent_path() / "transforms.json");
    EXPECT_FALSE(t.contains("fl_x"));
    ASSERT_EQ(t.at("frames").size(), 2u);
    EXPECT_EQ(t["frames"][1]["orthographic"], true);
    EXPECT_FALSE(t["frames"][1].contains("camera_angle_x"));
    expect_frames_match_camera_files(scene.parent_path(), t, /*shared=*/false);
}

// The PLY's vertices as export-mesh wrote them (binary little-endian float x, y, z).
std::vector<glm::vec3> ply_vertices(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    size_t count = 0;
    while (std::getline(in, line) && line != "end_header")
        if (line.starts_with("element vertex ")) count = std::stoul(line.substr(15));
    std::vector<glm::vec3> out(count);
    for (glm::vec3& p : out)
        for (int k = 0; k < 3; ++k) {
            unsigned char b[4];
            in.read(reinterpret_cast<char*>(b), 4);
            p[k] = std::bit_cast<float>(uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 |
                                        uint32_t(b[3]) << 24);
        }
    return out;
}

TEST(TransformsJson, ExportMeshIsTheModelOnceWithItsWorldPositions) {
    test::TempDir dir;
    BatchOptions options;
    options.output_dir = dir.file("out");
    const std::string model = "builtin:torus";
    BatchDefaults d;
    d.views = "turntable:2";
    d.styles = "lambert,toon";
    d.options.size = {24, 24};
    d.options.export_mesh = "ply";
    d.options.camera.up_axis = UpAxis::PosZ;  // turns the camera, never the mesh
    const auto jobs = expand_jobs({{model, "t"}}, d);
    ASSERT_EQ(run_batch(jobs, options).done, 4u);
    EXPECT_FALSE(fs::exists(dir.file("out/t/toon/transforms.json")));  // only when asked for
    const std::vector<glm::vec3> written = ply_vertices(dir.file("out/t.mesh.ply"));
    const Mesh mesh = load_mesh(model);
    ASSERT_EQ(written.size(), mesh.positions.size());
    for (size_t i = 0; i < written.size(); ++i) ASSERT_EQ(written[i], mesh.positions[i]) << i;
    const json meta = read_json(dir.file("out/t/toon/az180_el20.json"));
    EXPECT_EQ(meta["outputs"]["mesh"], "../../t.mesh.ply");

    // The mesh is an output: without it the jobs are not complete.
    fs::remove(dir.file("out/t.mesh.ply"));
    EXPECT_EQ(run_batch(jobs, options).done, 4u);
    EXPECT_TRUE(fs::is_regular_file(dir.file("out/t.mesh.ply")));
}

TEST(TransformsJson, ExportMeshInABatchTakesAFormat) {
    BatchDefaults d;
    d.options.export_mesh = "a.ply";
    EXPECT_THROW(expand_jobs({{"builtin:sphere", "s"}}, d), InputError);
    d.options.export_mesh = "obj";
    EXPECT_EQ(expand_jobs({{"builtin:sphere", "s"}}, d).size(), 1u);
}

}  // namespace
}  // namespace inkshade
