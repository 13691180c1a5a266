// One frame of the sample avatar (scripts/avatar-sample --spring-hair) in mtoon at 2 s of its
// "sway" animation, loaded, posed and rendered (320x240, headless GL), with its ponytail's spring
// bones simulated (120 steps) and with them off: the cost of spring bones in a frame (issue
// criterion: at most 1.3x); AvatarLoad the load and pose alone, where the simulation's cost is.
// The avatar is written once into /tmp and removed at exit.
//   inkshade_bench --benchmark_filter=Avatar
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "inkshade/io.hpp"
#include "inkshade/renderer.hpp"
#include "inkshade/scene.hpp"

namespace {

struct Avatar {
    std::string path = (std::filesystem::temp_directory_path() / "inkshade_bench_ponytail.vrm").string();
    Avatar() {
        const std::string cmd =
            "python3 '" + std::string(INKSHADE_SOURCE_DIR) + "/scripts/avatar-sample' --spring-hair '" + path + "'";
        if (std::system(cmd.c_str()) != 0) std::abort();
    }
    ~Avatar() { std::filesystem::remove(path); }
};

const Avatar& avatar() {
    static const Avatar a;
    return a;
}

// The frame's scene: mtoon, 320x240, "sway" at 2 s, spring bones as state.range(0) says.
inkshade::Scene avatar_scene(const benchmark::State& state) {
    inkshade::SceneRequest request;
    request.model = avatar().path;
    request.style = "mtoon";
    request.size = {320, 240};
    request.animation = "sway";
    request.time = 2.0f;
    request.spring_bones = state.range(0) != 0;
    return inkshade::make_scene(request);
}

void AvatarFrame(benchmark::State& state) {
    static inkshade::Renderer renderer;
    const inkshade::Scene scene = avatar_scene(state);
    for (auto _ : state) {
        const inkshade::Mesh mesh = inkshade::load_mesh(scene.model, scene.load_options());
        const inkshade::Camera camera = scene.frame(mesh);
        renderer.set_mesh(mesh);
        benchmark::DoNotOptimize(inkshade::render_scene(renderer, scene, camera, scene.light(mesh.bounds(), camera)));
    }
}
BENCHMARK(AvatarFrame)->ArgName("spring_bones")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void AvatarLoad(benchmark::State& state) {
    const inkshade::Scene scene = avatar_scene(state);
    for (auto _ : state) benchmark::DoNotOptimize(inkshade::load_mesh(scene.model, scene.load_options()));
}
BENCHMARK(AvatarLoad)->ArgName("spring_bones")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(1.0);

}  // namespace
