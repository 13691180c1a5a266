// Curvature, principal directions and the curvature-derivative tensor (Rusinkiewicz 2004) on a
// noisy torus knot of about 1 M triangles, on 1 and 2 threads. Target: ≤ 280 ms on one thread
// (trimesh2's compute_curvatures + compute_dcurv take about 557 ms on the same machine).
//   inkshade_bench --benchmark_filter=Curvature
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdint>

#include "geometry/builtin_models.hpp"
#include "geometry/curvature.hpp"
#include "geometry/normals.hpp"

namespace {

using inkshade::Mesh;

// Torus knot with 4096 x 128 quads (1,048,576 triangles), each vertex moved along its normal by
// up to ±0.2 % of the tube radius (a deterministic hash, like scanner noise), normals recomputed.
const Mesh& noisy_knot() {
    static const Mesh mesh = [] {
        const float tube = 0.15f;
        Mesh m = inkshade::builtin::torus_knot(2, 3, tube, 4096, 128);
        for (size_t v = 0; v < m.positions.size(); ++v) {
            uint32_t h = uint32_t(v) * 2654435761u;
            h ^= h >> 15;
            h *= 2246822519u;
            h ^= h >> 13;
            const float noise = (float(h & 0xffffu) / 65535.0f - 0.5f) * 2.0f;  // [-1, 1]
            m.positions[v] += 0.002f * tube * noise * m.normals[v];
        }
        m.normals = inkshade::geometry::angle_weighted_vertex_normals(m);
        return m;
    }();
    return mesh;
}

void BM_Curvature(benchmark::State& state) {
    const Mesh& mesh = noisy_knot();
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    for (auto _ : state) {
        const auto c = inkshade::geometry::compute_curvature(mesh, mesh.normals);
        benchmark::DoNotOptimize(c.dcurv.data());
    }
    state.counters["triangles"] = double(mesh.triangle_count());
    state.counters["threads"] = double(state.range(0));
}

}  // namespace

BENCHMARK(BM_Curvature)
    ->Arg(1)
    ->Arg(2)
    ->Iterations(5)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true)
    ->Unit(benchmark::kMillisecond);
