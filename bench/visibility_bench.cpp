// Per-view vector line drawing with hidden-line removal on a torus knot of 1,048,576
// triangles (builtin:torus-knot:segments=4096,tube-segments=128), 1024x1024 image: extraction
// + ray-cast visibility + chaining + projection, the mesh-wide work (Embree BVH, curvature,
// adjacency) done once before timing. Issue 6's budget: ≤ 30 ms per view on 2 cores.
//   inkshade_bench --benchmark_filter=Visibility --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "geometry/builtin_models.hpp"
#include "geometry/contours.hpp"
#include "geometry/visibility.hpp"
#include "inkshade/line_drawing.hpp"
#include "noisy_knot.hpp"

namespace {

using namespace inkshade;

constexpr int kSize = 1024;

struct Scene {
    Mesh mesh;
    Camera camera;
};

const Scene& scene() {
    static const Scene s = [] {
        Scene sc;
        sc.mesh = builtin::torus_knot(2, 3, 0.15f, 4096, 128);
        CameraOptions o;  // the CLI's default auto-framed three-quarter view
        sc.camera = frame_camera(sc.mesh.bounds(), o, 1.0f);
        return sc;
    }();
    return s;
}

// One extractor per line set, warmed up (BVH, curvature) before timing.
LineExtractor& extractor(const std::vector<LineSettings>& lines) {
    static LineExtractor e(scene().mesh);
    e.draw(scene().camera, kSize, kSize, lines);
    return e;
}

void draw_view(benchmark::State& state, const std::vector<LineSettings>& lines) {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    LineExtractor& e = extractor(lines);
    size_t paths = 0, points = 0;
    for (auto _ : state) {
        const LineDrawing d = e.draw(scene().camera, kSize, kSize, lines);
        paths = points = 0;
        for (const LineLayer& l : d.layers)
            for (const LinePath& p : l.visible) ++paths, points += p.points.size();
        benchmark::DoNotOptimize(d.layers.data());
    }
    state.counters["threads"] = double(state.range(0));
    state.counters["triangles"] = double(scene().mesh.triangle_count());
    state.counters["paths"] = double(paths);
    state.counters["points"] = double(points);
}

void BM_VisibilityContourView(benchmark::State& state) { draw_view(state, {{"contour", {}}}); }

// Contours + suggestive contours on the noisy knot (bench/noisy_knot.hpp), the scan stand-in of
// issue 20's speed goal (≤ 40 ms a view on 2 cores, exact visibility): 30 k contour segments
// and 80 k suggestive ones a view, against 17 k and few on the smooth knot.
void BM_VisibilityScanView(benchmark::State& state) {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    static const Camera camera = frame_camera(bench::noisy_knot().bounds(), CameraOptions{}, 1.0f);
    static LineExtractor e(bench::noisy_knot());
    const std::vector<LineSettings> lines = {{"contour", {}}, {"suggestive", {}}};
    e.draw(camera, kSize, kSize, lines);  // mesh-wide data before timing
    size_t paths = 0;
    std::vector<LineTiming> timings;
    double extract_ms = 0.0, visibility_ms = 0.0;
    for (auto _ : state) {
        const LineDrawing d = e.draw(camera, kSize, kSize, lines, &timings);
        paths = 0;
        for (const LineLayer& l : d.layers) paths += l.visible.size();
        benchmark::DoNotOptimize(d.layers.data());
        for (const LineTiming& t : timings) {
            if (t.stage == "extract") extract_ms += t.milliseconds;
            if (t.stage == "visibility") visibility_ms += t.milliseconds;
        }
    }
    state.counters["threads"] = double(state.range(0));
    state.counters["paths"] = double(paths);
    // Wall milliseconds a view of the two stages that matter (the rest: chaining, projection).
    state.counters["extract_ms"] = benchmark::Counter(extract_ms, benchmark::Counter::kAvgIterations);
    state.counters["visibility_ms"] = benchmark::Counter(visibility_ms, benchmark::Counter::kAvgIterations);
}

// The default vector set of `inkshade lines` (suggestive with the curvature already cached).
void BM_VisibilityDefaultView(benchmark::State& state) {
    draw_view(state, {{"contour", {}}, {"suggestive", {}}, {"crease", {}}, {"border", {}}});
}

// The ray-casting split alone, on the contour segments of the view.
void BM_VisibilitySplitOnly(benchmark::State& state) {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    const Scene& s = scene();
    static const geometry::RayScene rays(s.mesh);
    const geometry::ImageProjection view(s.camera, kSize, kSize);
    const auto segments = geometry::extract_contours(s.mesh, s.mesh.normals, s.camera);
    size_t hidden = 0;
    for (auto _ : state) {
        const auto split = geometry::split_by_visibility(rays, s.mesh, view, segments);
        hidden = split.hidden.size();
        benchmark::DoNotOptimize(split.visible.data());
    }
    state.counters["threads"] = double(state.range(0));
    state.counters["segments"] = double(segments.size());
    state.counters["hidden"] = double(hidden);
}

// Once per mesh: building the Embree BVH of 1 M triangles.
void BM_VisibilitySceneBuild(benchmark::State& state) {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    for (auto _ : state) {
        geometry::RayScene rays(scene().mesh);
        benchmark::DoNotOptimize(rays.tolerance());
    }
    state.counters["threads"] = double(state.range(0));
}

}  // namespace

BENCHMARK(BM_VisibilityContourView)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VisibilityScanView)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VisibilityDefaultView)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VisibilitySplitOnly)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VisibilitySceneBuild)->Arg(2)->Unit(benchmark::kMillisecond)->Iterations(3);
