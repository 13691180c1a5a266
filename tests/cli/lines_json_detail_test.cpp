// `inkshade lines --lines-json-detail full` and the batch format lines-json: each point's world
// position re-projected through the camera file (docs/aov.md) lands on its image point, its
// triangle's corners weighted by its barycentric weights give it back, its tangent is unit and
// along the polyline, and the basic file is the one without the detail.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "cli/run_cli.hpp"
#include "inkshade/io.hpp"
#include "io/tar_reader.hpp"

namespace inkshade::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

glm::dmat4 matrix(const json& rows) {
    glm::dmat4 m(1.0);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = rows[r][c].get<double>();
    return m;
}

glm::dvec3 vec3(const json& v) { return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}; }
glm::dvec2 vec2(const json& v) { return {v[0].get<double>(), v[1].get<double>()}; }

// The image point of a world point through a camera file: OpenCV's pinhole (or orthographic)
// K with world_to_camera_opencv, docs/aov.md.
glm::dvec2 reproject(const json& cam, const glm::dvec3& world) {
    const glm::dvec4 c = matrix(cam["world_to_camera_opencv"]) * glm::dvec4(world, 1.0);
    const double s = cam["projection"] == "orthographic" ? 1.0 : c.z;
    return {cam["K"][0][0].get<double>() * c.x / s + cam["K"][0][2].get<double>(),
            cam["K"][1][1].get<double>() * c.y / s + cam["K"][1][2].get<double>()};
}

struct DetailCounts {
    size_t points = 0, hidden_paths = 0;
    double worst_px = 0.0, worst_barycentric = 0.0;
};

// Every point of every path of `lines` (a --lines-json-detail full file) checked against the
// camera file and the mesh; returns what was checked.
DetailCounts check_detail(const json& lines, const json& cam, const Mesh& mesh) {
    DetailCounts n;
    const BoundingBox box = mesh.bounds();
    const double scale = glm::length(glm::dvec3(box.max - box.min));
    for (const json& layer : lines["layers"])
        for (const json& path : layer["paths"]) {
            const json& points = path["points"];
            const size_t count = points.size();
            for (const char* key : {"world", "face", "barycentric", "tangent", "normal"})
                EXPECT_EQ(path[key].size(), count) << key;
            EXPECT_EQ(path["hidden"].get<bool>(), path["level"].get<int>() > 0) << "occlusion level and hidden";
            n.hidden_paths += path["hidden"].get<bool>();
            const bool closed = path["closed"];
            for (size_t i = 0; i < count; ++i) {
                const glm::dvec2 p = vec2(points[i]);
                const glm::dvec3 world = vec3(path["world"][i]);
                n.worst_px = std::max(n.worst_px, glm::length(reproject(cam, world) - p));
                const int face = path["face"][i];
                EXPECT_GE(face, 0);
                EXPECT_LT(size_t(face), mesh.triangle_count());
                if (face < 0 || size_t(face) >= mesh.triangle_count()) continue;
                const glm::uvec3 t = mesh.triangles[size_t(face)];
                const glm::dvec3 b = vec3(path["barycentric"][i]);
                const glm::dvec3 back = b.x * glm::dvec3(mesh.positions[t.x]) + b.y * glm::dvec3(mesh.positions[t.y]) +
                                        b.z * glm::dvec3(mesh.positions[t.z]);
                n.worst_barycentric = std::max(n.worst_barycentric, glm::length(back - world) / scale);
                // The tangent: unit, along the central difference of the neighbours (one-sided at
                // an open end); the normal is it turned +90 degrees: (-ty, tx).
                const glm::dvec2 tangent = vec2(path["tangent"][i]), normal = vec2(path["normal"][i]);
                EXPECT_NEAR(glm::length(tangent), 1.0, 1e-6);
                EXPECT_EQ(normal, glm::dvec2(-tangent.y, tangent.x));
                const size_t next = closed ? (i + 1) % count : std::min(i + 1, count - 1);
                const size_t prev = closed ? (i + count - 1) % count : (i > 0 ? i - 1 : 0);
                const glm::dvec2 d = vec2(points[next]) - vec2(points[prev]);
                const double len = glm::length(d);
                if (len < 0.05) continue;  // rounded to 1e-3 px: too short to give a direction
                EXPECT_GT(glm::dot(tangent, d / len), 0.0);
                EXPECT_LT(std::abs(tangent.x * d.y - tangent.y * d.x) / len, 2e-3 / len + 1e-4) << i;
                ++n.points;
            }
        }
    return n;
}

// The acceptance test: a sphere and a torus, perspective and orthographic, contours and hidden
// lines (and dashes, whose inserted points are placed perspective-correctly).
TEST(LinesJsonDetail, WorldPointsReprojectThroughTheCameraFile) {
    for (const char* model : {"builtin:sphere", "builtin:torus"})
        for (const char* projection : {"", " --ortho"}) {
            SCOPED_TRACE(std::string(model) + projection);
            TempDir dir;
            // The torus's axis up (z) and seen from above its plane: its inner contour passes behind
            // the tube (occlusion levels 1 and 2).
            const std::string camera =
                std::string(" --size 320x240 --up-axis z --azimuth 30 --elevation 25 ") + projection;
            auto r = run_cli("lines " + std::string(model) + camera +
                             " --lines contour,suggestive --hidden --set contour.dash=6,3 --lines-json-detail full"
                             " --lines-json " +
                             dir.file("l.json") + " -o " + dir.file("l.svg"));
            ASSERT_EQ(r.status, 0) << r.err;
            r = run_cli("render " + std::string(model) + camera + " --aov camera -o " + dir.file("r.png"));
            ASSERT_EQ(r.status, 0) << r.err;
            const json lines = json::parse(slurp(dir.file("l.json")));
            const json cam = json::parse(slurp(dir.file("r.camera.json")));
            const DetailCounts n = check_detail(lines, cam, load_mesh(model));
            EXPECT_GT(n.points, 200u);
            if (std::string(model) == "builtin:torus") {
                EXPECT_GT(n.hidden_paths, 1u);
            }
            EXPECT_LT(n.worst_px, 0.01) << "re-projection of the world points";
            EXPECT_LT(n.worst_barycentric, 1e-5) << "barycentric weights of the triangles' corners";
        }
}

// A file's loose lines lie on no triangle: face -1, weights 0, and their world points still
// project onto their image points; the box's creases carry its faces.
TEST(LinesJsonDetail, LooseLinesHaveNoFace) {
    TempDir dir;
    std::string obj;
    for (int i = 0; i < 8; ++i)
        obj += std::string("v ") + (i & 1 ? "1" : "-1") + (i & 2 ? " 1" : " -1") + (i & 4 ? " 1\n" : " -1\n");
    obj += "v -2 0 0\nv 2 0 0\nf 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\nl 9 10\n";
    const std::string model = dir.write("box.obj", obj);
    const std::string camera = " --size 320x240 --azimuth 30 --elevation 25";
    auto r = run_cli("lines " + model + camera + " --lines crease,loose -o " + dir.file("b.svg") +
                     " --lines-json-detail full --lines-json " + dir.file("b.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli("render " + model + camera + " --aov camera -o " + dir.file("r.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    const json lines = json::parse(slurp(dir.file("b.json")));
    const json cam = json::parse(slurp(dir.file("r.camera.json")));
    ASSERT_EQ(lines["layers"].size(), 2u);
    size_t loose = 0, crease = 0;
    for (const json& layer : lines["layers"])
        for (const json& path : layer["paths"])
            for (size_t i = 0; i < path["points"].size(); ++i) {
                EXPECT_LT(glm::length(reproject(cam, vec3(path["world"][i])) - vec2(path["points"][i])), 0.01);
                if (layer["type"] == "loose") {
                    EXPECT_EQ(path["face"][i], -1);
                    EXPECT_EQ(vec3(path["barycentric"][i]), glm::dvec3(0.0));
                    ++loose;
                } else {
                    EXPECT_GE(path["face"][i].get<int>(), 0);
                    ++crease;
                }
            }
    EXPECT_GT(loose, 1u);
    EXPECT_GT(crease, 4u);
}

// Basic is the default and the file without the detail; full adds keys to each path and
// changes nothing else.
TEST(LinesJsonDetail, FullAddsKeysToTheBasicFile) {
    TempDir dir;
    const std::string base = "lines builtin:torus --size 160x120 --lines contour,crease -o " + dir.file("a.svg") + " ";
    ASSERT_EQ(run_cli(base + "--lines-json " + dir.file("none.json")).status, 0);
    ASSERT_EQ(run_cli(base + "--lines-json-detail basic --lines-json " + dir.file("basic.json")).status, 0);
    ASSERT_EQ(run_cli(base + "--lines-json-detail full --lines-json " + dir.file("full.json")).status, 0);
    EXPECT_EQ(slurp(dir.file("none.json")), slurp(dir.file("basic.json")));
    json full = json::parse(slurp(dir.file("full.json")));
    size_t paths = 0;
    for (json& layer : full["layers"])
        for (json& path : layer["paths"]) {
            for (const char* key : {"world", "face", "barycentric", "tangent", "normal"}) {
                EXPECT_TRUE(path.contains(key)) << key;
                path.erase(key);
            }
            ++paths;
        }
    EXPECT_GT(paths, 0u);
    EXPECT_EQ(full, json::parse(slurp(dir.file("basic.json"))));
}

TEST(LinesJsonDetail, BadValuesAreOneLineExitTwo) {
    TempDir dir;
    auto r = run_cli("lines builtin:sphere --size 32x32 -o " + dir.file("a.svg") + " --lines-json " +
                     dir.file("a.json") + " --lines-json-detail fulll");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--lines-json-detail"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("basic"), std::string::npos) << r.err;
    r = run_cli("lines builtin:sphere --size 32x32 -o " + dir.file("a.svg") + " --lines-json-detail full");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--lines-json"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

// A batch job writes STEM.lines.json (format lines-json) with its lines-json-detail; its
// metadata's camera re-projects the points as the camera file does, and old formats keep
// their hashes.
TEST(LinesJsonDetail, BatchWritesTheLinesJsonOfEachJob) {
    TempDir dir;
    const std::string manifest = dir.write("jobs.csv",
                                           "model,name,styles,size,format,lines-json-detail,ortho\n"
                                           "builtin:sphere,s,ink-vector,96x64,lines-json,full,false\n"
                                           "builtin:torus,t,ink-vector,96x64,\"svg,lines-json\",,true\n");
    const std::string out = dir.file("ds");
    auto r = run_cli("batch " + manifest + " -o " + out + " -q");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string s = out + "/s/ink-vector/az035_el20", t = out + "/t/ink-vector/az035_el20";
    EXPECT_FALSE(fs::exists(s + ".png"));
    EXPECT_FALSE(fs::exists(s + ".svg"));
    EXPECT_TRUE(fs::is_regular_file(t + ".svg"));
    const json meta = json::parse(slurp(s + ".json"));
    EXPECT_EQ(meta["outputs"]["lines_json"], "az035_el20.lines.json");
    EXPECT_EQ(meta["lines_json_detail"], "full");
    // The metadata's camera: clip = P V x, then GL's viewport with y down (docs/cli.md).
    const json lines = json::parse(slurp(s + ".lines.json"));
    const glm::dmat4 pv = matrix(meta["camera"]["projection_matrix"]) * matrix(meta["camera"]["view_matrix"]);
    size_t points = 0;
    for (const json& layer : lines["layers"])
        for (const json& path : layer["paths"])
            for (size_t i = 0; i < path["points"].size(); ++i) {
                const glm::dvec4 clip = pv * glm::dvec4(vec3(path["world"][i]), 1.0);
                const glm::dvec2 image((clip.x / clip.w + 1.0) * 0.5 * 96, (1.0 - clip.y / clip.w) * 0.5 * 64);
                EXPECT_LT(glm::length(image - vec2(path["points"][i])), 0.01);
                ++points;
            }
    EXPECT_GT(points, 50u);
    // The torus's is basic: the same text `inkshade lines` writes for the job.
    const json tmeta = json::parse(slurp(t + ".json"));
    EXPECT_FALSE(tmeta.contains("lines_json_detail"));
    r = run_cli("lines builtin:torus --style ink-vector --size 96x64 --ortho --azimuth 35 --elevation 20 -o " +
                dir.file("t.svg") + " --lines-json " + dir.file("t.json"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(t + ".lines.json"), slurp(dir.file("t.json")));
    // Resumed: complete jobs are skipped while their lines JSON is there, rendered again when not.
    fs::remove(t + ".lines.json");
    r = run_cli("batch " + manifest + " -o " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::is_regular_file(t + ".lines.json"));
    EXPECT_NE(r.out.find("1 done, 1 skipped"), std::string::npos) << r.out;
    // In WebDataset shards the sample carries KEY.lines.json with the folder's bytes.
    r = run_cli("batch " + manifest + " -o " + dir.file("wds") + " --layout webdataset -q");
    ASSERT_EQ(r.status, 0) << r.err;
    std::map<std::string, std::string> shard;
    for (const auto& e : fs::directory_iterator(dir.file("wds")))
        if (e.path().extension() == ".tar") {
            io::TarReader reader(e.path().string());
            while (const auto m = reader.next()) shard[m->name] = reader.read(*m);
        }
    EXPECT_EQ(shard["s/ink-vector/az035_el20.lines.json"], slurp(s + ".lines.json"));
    EXPECT_EQ(shard["t/ink-vector/az035_el20.lines.json"], slurp(t + ".lines.json"));
}

}  // namespace
}  // namespace inkshade::test
