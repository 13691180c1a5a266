// Per-view object-space line extraction on a torus knot of 1,048,576 triangles: contours,
// suggestive contours (DeCarlo et al. 2004 / rtsc) and chaining, curvature computed once
// beforehand (it does not depend on the view). Issue 6's budget for extraction + visibility +
// chaining is 30 ms on 2 cores; the extraction here should be well under it.
//   inkshade_bench --benchmark_filter=Lines --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true
// Also, on the 100 k teapot, hatching's once-per-mesh setup and the SVG writing of all
// thirteen object-space types (docs/benchmarks.md):
//   inkshade_bench --benchmark_filter='Hatching|Svg' --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true
// and what the newer line kinds add to a teapot view (BM_LinesNewKinds).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "geometry/builtin_models.hpp"
#include "geometry/chaining.hpp"
#include "geometry/contours.hpp"
#include "geometry/creases.hpp"
#include "geometry/curvature.hpp"
#include "geometry/hatching.hpp"
#include "geometry/suggestive_contours.hpp"
#include "inkshade/line_drawing.hpp"

namespace {

using namespace inkshade;

struct Scene {
    Mesh mesh;
    geometry::Curvature curvature;
    Camera camera;
};

// builtin:torus-knot:segments=4096,tube-segments=128 (2 × 4096 × 128 triangles), seen in a
// three-quarter view from about three bounding radii.
const Scene& scene() {
    static const Scene s = [] {
        Scene sc;
        sc.mesh = builtin::torus_knot(2, 3, 0.15f, 4096, 128);
        sc.curvature = geometry::compute_curvature(sc.mesh, sc.mesh.normals);
        sc.camera.eye = {3.0f, 2.0f, 4.0f};
        sc.camera.fov_degrees = 40.0f;
        return sc;
    }();
    return s;
}

void set_counters(benchmark::State& state, size_t segments) {
    state.counters["triangles"] = double(scene().mesh.triangle_count());
    state.counters["threads"] = double(state.range(0));
    state.counters["segments"] = double(segments);
}

void BM_LinesContours(benchmark::State& state) {
    const Scene& s = scene();
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    size_t n = 0;
    for (auto _ : state) {
        const auto segs = geometry::extract_contours(s.mesh, s.mesh.normals, s.camera);
        n = segs.size();
        benchmark::DoNotOptimize(segs.data());
    }
    set_counters(state, n);
}

void BM_LinesSuggestive(benchmark::State& state) {
    const Scene& s = scene();
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    size_t n = 0;
    for (auto _ : state) {
        const auto segs = geometry::extract_suggestive_contours(s.mesh, s.mesh.normals, s.curvature, s.camera);
        n = segs.size();
        benchmark::DoNotOptimize(segs.data());
    }
    set_counters(state, n);
}

// What a frame of vector output costs before visibility: both line types, chained.
void BM_LinesPerView(benchmark::State& state) {
    const Scene& s = scene();
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    size_t n = 0;
    for (auto _ : state) {
        const auto contours = geometry::chain_segments(geometry::extract_contours(s.mesh, s.mesh.normals, s.camera));
        const auto suggestive = geometry::chain_segments(
            geometry::extract_suggestive_contours(s.mesh, s.mesh.normals, s.curvature, s.camera));
        n = contours.size() + suggestive.size();
        benchmark::DoNotOptimize(contours.data());
        benchmark::DoNotOptimize(suggestive.data());
    }
    set_counters(state, n);
    state.counters.erase("segments");
    state.counters["polylines"] = double(n);
}

// View-independent, once per mesh: edge adjacency and crease classification.
void BM_LinesCreases(benchmark::State& state) {
    const Scene& s = scene();
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    size_t n = 0;
    for (auto _ : state) {
        const auto adjacency = geometry::build_edge_adjacency(s.mesh);
        const auto creases = geometry::extract_creases(s.mesh, adjacency);
        n = creases.ridges.size() + creases.valleys.size() + creases.borders.size();
        benchmark::DoNotOptimize(adjacency.edges.data());
    }
    set_counters(state, n);
}

// The 100 k teapot (builtin:teapot:subdivisions=40, 102,080 triangles) with its curvature and
// adjacency, for the once-per-mesh hatching setup.
struct Teapot {
    Mesh mesh;
    geometry::Curvature curvature;
    geometry::EdgeAdjacency adjacency;
};

const Teapot& teapot() {
    static const Teapot t = [] {
        Teapot tp;
        tp.mesh = builtin::teapot(40);
        tp.curvature = geometry::compute_curvature(tp.mesh, tp.mesh.normals);
        tp.adjacency = geometry::build_edge_adjacency(tp.mesh);
        return tp;
    }();
    return t;
}

// The `hatch` line type's defaults: 30 smoothing rounds, two levels, both families.
geometry::HatchOptions hatch_defaults() {
    geometry::HatchOptions o;
    o.smoothing = 30;
    return o;
}

// Hatching's whole per-mesh setup: cross field and streamlines (Hertzmann & Zorin 2000,
// Jobard & Lefer 1997).
void BM_HatchingSetup(benchmark::State& state) {
    const Teapot& t = teapot();
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    size_t n = 0;
    for (auto _ : state) {
        const geometry::Hatching h =
            geometry::trace_hatching(t.mesh, t.mesh.normals, t.curvature, t.adjacency, hatch_defaults());
        n = h.strokes.size();
        benchmark::DoNotOptimize(h.strokes.data());
    }
    state.counters["triangles"] = double(t.mesh.triangle_count());
    state.counters["threads"] = double(state.range(0));
    state.counters["strokes"] = double(n);
}

// The cross field alone (30 rounds of averaging).
void BM_HatchingField(benchmark::State& state) {
    const Teapot& t = teapot();
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    for (auto _ : state) {
        const auto field = geometry::hatch_direction_field(t.mesh, t.mesh.normals, t.curvature, 30);
        benchmark::DoNotOptimize(field.data());
    }
    state.counters["threads"] = double(state.range(0));
}

// SVG writing of the teapot's thirteen object-space types (what `inkshade lines` writes; the
// Bézier fit of Schneider 1990 is most of it): the drawing is made once, format_svg timed.
void BM_SvgBezierFit(benchmark::State& state) {
    static const LineDrawing drawing = [] {
        Mesh mesh = builtin::teapot(40);
        const BoundingBox box = mesh.bounds();
        const Camera camera = frame_camera(box, CameraOptions{}, 1.0f);
        LineExtractor extractor(std::move(mesh));
        std::vector<LineSettings> lines;
        for (const char* type :
             {"contour", "suggestive", "crease", "border", "ridge", "valley", "intersection", "isophote", "topo",
              "suggestive-highlight", "principal-highlight", "apparent-ridge", "hatch"})
            lines.push_back({type, {}});
        return extractor.draw(camera, 1024, 1024, lines);
    }();
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(state.range(0)));
    size_t bytes = 0, paths = 0;
    for (const LineLayer& layer : drawing.layers) paths += layer.visible.size() + layer.hidden.size();
    for (auto _ : state) {
        const std::string svg = format_svg(drawing, glm::vec4(1.0f));
        bytes = svg.size();
        benchmark::DoNotOptimize(svg.data());
    }
    state.counters["threads"] = double(state.range(0));
    state.counters["paths"] = double(paths);
    state.counters["bytes"] = double(bytes);
}

// A view of the 100 k teapot (builtin:teapot:subdivisions=40) on a warm extractor: the contour
// alone (arg 0), then with the newer kinds beside it (arg 1: light-contour, material-boundary,
// clip-boundary, silhouette, external-contour, cast-shadow, loose), or with cast-shadow alone
// (arg 2: its rays towards the default key light); the difference is what those kinds cost a
// frame (issue 34: at most 0.1 s).
void BM_LinesNewKinds(benchmark::State& state) {
    static Mesh mesh = builtin::teapot(40);
    static const Camera camera = frame_camera(mesh.bounds(), CameraOptions{}, 1.0f);
    static LineExtractor extractor(mesh);
    std::vector<LineSettings> lines = {{"contour", {}}};
    if (state.range(0) == 1)
        for (const char* type : {"light-contour", "material-boundary", "clip-boundary", "silhouette",
                                 "external-contour", "cast-shadow", "loose"})
            lines.push_back({type, {}});
    if (state.range(0) == 2) lines.push_back({"cast-shadow", {}});
    extractor.draw(camera, 1024, 1024, lines);  // mesh-wide data and the ray scene, untimed
    size_t paths = 0;
    for (auto _ : state) {
        const LineDrawing drawing = extractor.draw(camera, 1024, 1024, lines);
        paths = 0;
        for (const LineLayer& layer : drawing.layers) paths += layer.visible.size();
        benchmark::DoNotOptimize(paths);
    }
    state.counters["layers"] = double(lines.size());
    state.counters["paths"] = double(paths);
}

}  // namespace

BENCHMARK(BM_LinesNewKinds)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HatchingSetup)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HatchingField)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SvgBezierFit)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LinesContours)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LinesSuggestive)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LinesPerView)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LinesCreases)->Arg(1)->Unit(benchmark::kMillisecond);
