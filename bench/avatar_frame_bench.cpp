// One frame of the sample avatar (scripts/avatar-sample --spring-hair) in mtoon at 2 s of its
// "sway" animation, loaded, posed and rendered (320x240, headless GL), with its ponytail's spring
// bones simulated (120 steps) and with them off: the cost of spring bones in a frame (issue
// criterion: at most 1.3x). The avatar is written once into /tmp and removed at exit.
//   inkshade_bench --benchmark_filter=AvatarFrame
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

void AvatarFrame(benchmark::State& state) {
    static const Avatar avatar;
    static inkshade::Renderer renderer;
    inkshade::SceneRequest request;
    request.model = avatar.path;
    request.style = "mtoon";
    request.size = {320, 240};
    request.animation = "sway";
    request.time = 2.0f;
    request.spring_bones = state.range(0) != 0;
    const inkshade::Scene scene = inkshade::make_scene(request);
    for (auto _ : state) {
        const inkshade::Mesh mesh = inkshade::load_mesh(scene.model, scene.load_options());
        const inkshade::Camera camera = scene.frame(mesh);
        renderer.set_mesh(mesh);
        benchmark::DoNotOptimize(inkshade::render_scene(renderer, scene, camera, scene.light(mesh.bounds(), camera)));
    }
}
BENCHMARK(AvatarFrame)->ArgName("spring_bones")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
