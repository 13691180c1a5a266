// `render --export-mesh` and `lines --export-mesh`: the mesh in the camera file's world, so that
// its vertices re-project onto the image where the depth AOV holds their depth.
#include <gtest/gtest.h>

#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "cli/exr_channel.hpp"
#include "cli/json_matrix.hpp"
#include "cli/run_cli.hpp"
#include "inkshade/io.hpp"

namespace inkshade::test {
namespace {

namespace fs = std::filesystem;

// The EXR's depth channel Z, top row first.
std::vector<float> read_depth(const std::string& path, int& width, int& height) {
    return read_exr_channel(path, "Z", width, height);
}

std::vector<glm::vec3> obj_vertices(const std::string& path) {
    std::istringstream in(slurp(path));
    std::vector<glm::vec3> out;
    std::string tag;
    for (std::string line; std::getline(in, line);) {
        std::istringstream l(line);
        glm::vec3 p;
        if (l >> tag && tag == "v" && l >> p.x >> p.y >> p.z) out.push_back(p);
    }
    return out;
}

// A sphere seen with the z axis up: every vertex facing the camera is visible, and projected
// with the camera file's K and world_to_camera_opencv it lands on a pixel whose depth is its own.
TEST(ExportMeshCli, VerticesReprojectOntoTheirDepth) {
    TempDir dir;
    const std::string model = "builtin:sphere:rings=32,segments=64";
    auto r = run_cli("render " + model + " --up-axis z --azimuth 30 --elevation 40 --size 160x120 --aov depth -o " +
                     dir.file("a.png") + " --export-mesh " + dir.file("a.obj"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::vector<glm::vec3> vertices = obj_vertices(dir.file("a.obj"));
    const Mesh mesh = load_mesh(model);
    ASSERT_EQ(vertices, mesh.positions);  // the world positions exactly (shortest round-trip text)

    const nlohmann::json cam = nlohmann::json::parse(slurp(dir.file("a.camera.json")));
    const glm::dmat4 view = matrix(cam["world_to_camera_opencv"]);
    const glm::dvec3 eye(cam["eye"][0].get<double>(), cam["eye"][1].get<double>(), cam["eye"][2].get<double>());
    const double fx = cam["K"][0][0], fy = cam["K"][1][1], cx = cam["K"][0][2], cy = cam["K"][1][2];
    int w = 0, h = 0;
    const std::vector<float> depth = read_depth(dir.file("a.depth.exr"), w, h);
    int checked = 0;
    double worst = 0.0;
    for (const glm::vec3& p : vertices) {
        const glm::dvec3 n = glm::normalize(glm::dvec3(p));                    // the unit sphere's normal
        if (glm::dot(n, glm::normalize(eye - glm::dvec3(p))) < 0.5) continue;  // well inside the outline
        const glm::dvec4 c = view * glm::dvec4(glm::dvec3(p), 1.0);
        const double u = fx * c.x / c.z + cx, v = fy * c.y / c.z + cy;
        const int col = int(std::floor(u)), row = int(std::floor(v));
        ASSERT_TRUE(col >= 0 && col < w && row >= 0 && row < h);
        worst = std::max(worst, std::abs(double(depth[size_t(row) * size_t(w) + size_t(col)]) - c.z));
        ++checked;
    }
    EXPECT_GT(checked, 300);
    // Half a pixel (about 0.012 units here) across a surface at most 60 degrees from facing.
    EXPECT_LT(worst, 0.03);
}

TEST(ExportMeshCli, LinesWritesPlyAndBadNamesAreUsageErrors) {
    TempDir dir;
    auto r = run_cli("lines builtin:torus -o " + dir.file("a.svg") + " --export-mesh " + dir.file("a.PLY"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(slurp(dir.file("a.PLY")).starts_with("ply\nformat binary_little_endian 1.0\n"));
    for (const std::string& bad : {dir.file("a.stl"), std::string("ply")}) {
        r = run_cli("render builtin:torus -o " + dir.file("b.png") + " --export-mesh " + bad);
        EXPECT_EQ(r.status, 2) << bad;
        EXPECT_NE(r.err.find("--export-mesh"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir.file("b.png")));
    }
    r = run_cli("batch " + dir.write("jobs.csv", "model,views\nbuiltin:sphere,random:3\n") + " -o " + dir.file("out"));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("random:N:SEED"), std::string::npos) << r.err;
}

// The batch flags: --export-mesh ply once per model, --transforms-json per output directory.
TEST(ExportMeshCli, BatchWritesTheMeshAndTransformsJson) {
    TempDir dir;
    const std::string out = dir.file("out");
    auto r = run_cli("batch " + dir.write("jobs.csv", "model,views\nbuiltin:sphere,fibonacci:2\n") + " -o " + out +
                     " --size 32x32 --export-mesh ply --transforms-json -q");
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json t = nlohmann::json::parse(slurp(out + "/sphere/lambert/transforms.json"));
    ASSERT_EQ(t["frames"].size(), 2u);
    EXPECT_EQ(t["frames"][1]["file_path"], "fib2_001.png");
    EXPECT_TRUE(slurp(out + "/sphere.mesh.ply").starts_with("ply\n"));
    r = run_cli("batch " + dir.file("jobs.csv") + " -o " + out + " --export-mesh a.ply");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("export-mesh: batch takes obj or ply"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace inkshade::test
