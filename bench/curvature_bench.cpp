// Curvature, principal directions and the curvature-derivative tensor (Rusinkiewicz 2004) on a
// noisy torus knot of about 1 M triangles, on 1 and 2 threads. Target: ≤ 280 ms on one thread
// (trimesh2's compute_curvatures + compute_dcurv take about 557 ms on the same machine).
//   inkshade_bench --benchmark_filter=Curvature
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdint>

#include "geometry/curvature.hpp"
#include "noisy_knot.hpp"

namespace {

using inkshade::Mesh;

using inkshade::bench::noisy_knot;

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
