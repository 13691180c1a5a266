// Auto-smooth on scans without normals (docs/inputs.md#normals-and-hard-edges): what the
// default (--smooth-angle 30) costs over smooth normals (180) at load and per view, on
// 1 M-triangle stand-ins written once into /tmp as binary PLY without normals and removed at
// exit: 0, the noisy torus knot (noisy_knot.hpp: its noise tilts no edge past 30°); 1, the
// noisy sphere of the tests (6 × 289² quads, radial noise of ±0.2 edge lengths: 8 % of its
// edges past 30°); 2, the meshed cube of the tests (a CAD part, 12 × 289 hard edges). With
// INKSHADE_BENCH_SCAN=FILE (noisy_knot.hpp) stand-in 0 is that file's mesh instead.
//   inkshade_bench --benchmark_filter='AutoSmooth'
// Args: (mesh, smooth angle in degrees).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "../tests/geometry/analytic_meshes.hpp"
#include "geometry/contours.hpp"
#include "geometry/line_types/mesh_line_data.hpp"
#include "inkshade/io.hpp"
#include "noisy_knot.hpp"

namespace {

using namespace inkshade;

void write_ply(const Mesh& m, const std::string& path) {
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex " << m.vertex_count()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << m.triangle_count()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const glm::vec3& p : m.positions) out.write(reinterpret_cast<const char*>(&p), 12);
    for (const glm::uvec3& t : m.triangles) {
        const uint8_t three = 3;
        out.write(reinterpret_cast<const char*>(&three), 1);
        out.write(reinterpret_cast<const char*>(&t), 12);
    }
}

// The stand-in files, written on first use.
const std::string& scan_file(int64_t which) {
    struct Files {
        std::filesystem::path dir = std::filesystem::temp_directory_path() / "inkshade-auto-smooth-bench";
        std::string paths[3];
        Files() {
            std::filesystem::create_directories(dir);
            Mesh knot = bench::noisy_knot();
            knot.normals.clear();
            const Mesh meshes[3] = {knot, test::noisy_sphere(289, 0.2f), test::meshed_cube(289)};
            for (int i = 0; i < 3; ++i) {
                paths[i] = (dir / ("scan" + std::to_string(i) + ".ply")).string();
                write_ply(meshes[i], paths[i]);
            }
        }
        ~Files() {
            std::error_code ec;
            std::filesystem::remove_all(dir, ec);
        }
    };
    static const Files files;
    return files.paths[which];
}

LoadOptions with_angle(int64_t degrees) {
    LoadOptions options;
    options.smooth_angle = float(degrees);
    return options;
}

void BM_AutoSmoothLoad(benchmark::State& state) {
    const std::string& path = scan_file(state.range(0));
    size_t hard = 0;
    for (auto _ : state) {
        const Mesh m = load_mesh(path, with_angle(state.range(1)));
        hard = m.has_hard_edges() ? m.shading_normal_count() - m.vertex_count() : 0;
        benchmark::DoNotOptimize(m.positions.data());
    }
    state.counters["extra_normals"] = double(hard);
}

// One view's contour extraction as the `contour` line type does it (line_types/contour.cpp):
// the hard-edge table is built once per mesh, before the loop.
void BM_AutoSmoothContours(benchmark::State& state) {
    geometry::MeshLineData data(load_mesh(scan_file(state.range(0)), with_angle(state.range(1))));
    Camera camera;
    camera.eye = {3.0f, 2.0f, 4.0f};
    camera.target = glm::vec3(0.0f);
    const bool hard = data.mesh().has_hard_edges();
    if (hard) data.hard_edges();
    size_t segments = 0;
    for (auto _ : state) {
        const auto segs = hard ? geometry::extract_hard_edge_contours(data.mesh(), data.hard_edges(), camera)
                               : geometry::extract_contours(data.mesh(), data.normals(), camera);
        segments = segs.size();
        benchmark::DoNotOptimize(segs.data());
    }
    state.counters["segments"] = double(segments);
    state.counters["hard_edges"] = hard ? double(data.hard_edges().edges.size()) : 0.0;
}

}  // namespace

BENCHMARK(BM_AutoSmoothLoad)->ArgsProduct({{0, 1, 2}, {30, 180}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AutoSmoothContours)->ArgsProduct({{0, 1, 2}, {30, 180}})->Unit(benchmark::kMillisecond);
