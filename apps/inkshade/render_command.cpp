// `inkshade render MODEL -o out.png`: one image of a model with a shading model.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>

#include "commands.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "scene_options.hpp"

namespace inkshade::cli {

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n == 0 ? 0.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

// Fails early (before loading and rendering) when the output cannot be written there.
void check_output_path(const std::string& path) {
    namespace fs = std::filesystem;
    fs::path p(path);
    std::error_code ec;
    if (fs::is_directory(p, ec)) throw InputError(path + ": output is a directory");
    fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if (!fs::is_directory(dir, ec)) throw InputError(path + ": directory " + dir.string() + " does not exist");
}

// What the load got past (a texture not found, skipped primitives): one line each on stderr,
// not an error.
void print_warnings(const Mesh& mesh) {
    for (std::string line : mesh.warnings) {
        std::replace(line.begin(), line.end(), '\n', ' ');
        std::fprintf(stderr, "inkshade: warning: %s\n", line.c_str());
    }
}

struct RenderArgs {
    SceneOptions scene;
    std::string output;
    int timing = 0;
    std::string save_style;
};

int run_render(const RenderArgs& args) {
    check_output_path(args.output);
    const Style style = args.scene.resolved_style();
    const RenderOptions options = args.scene.render_options(style);
    const ShadingSelection& shading = style.shading;
    const auto load_start = std::chrono::steady_clock::now();
    const Mesh mesh = load_mesh(args.scene.model);
    print_warnings(mesh);
    const double load_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - load_start).count();
    const BoundingBox box = mesh.bounds();
    const Camera camera = args.scene.camera(box, float(options.width) / float(options.height));
    const Light light = args.scene.light(box, camera, style);

    Renderer renderer;
    renderer.set_mesh(mesh);
    Image image = renderer.render(camera, light, shading, style.lines, options);
    if (args.timing > 0) {
        std::map<std::string, std::vector<double>> per_pass;
        std::vector<std::string> order;
        std::vector<double> totals;
        for (int i = 0; i < args.timing; ++i) {
            std::vector<PassTiming> timings;
            auto start = std::chrono::steady_clock::now();
            image = renderer.render(camera, light, shading, style.lines, options, &timings);
            totals.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            for (const auto& t : timings) {
                if (!per_pass.count(t.pass)) order.push_back(t.pass);
                per_pass[t.pass].push_back(t.milliseconds);
            }
        }
        std::printf("timing: %s, %zu triangles, %dx%d, %d samples, %d frames on %s\n", shading.model.c_str(),
                    mesh.triangle_count(), options.width, options.height, options.samples, args.timing,
                    renderer.gl_renderer().c_str());
        for (const auto& pass : order) std::printf("  %-10s median %8.2f ms\n", pass.c_str(), median(per_pass[pass]));
        std::printf("  %-10s median %8.2f ms\n", "total", median(totals));
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        std::printf("  load %.0f ms, peak RSS %.0f MiB\n", load_ms, double(usage.ru_maxrss) / 1024.0);
    }
    write_png(args.output, image);
    if (!args.save_style.empty()) save_style(args.save_style, style);
    return 0;
}

}  // namespace

Command add_render_command(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "render a model to a PNG image");
    args->scene.add_to(*cmd);
    cmd->add_option("-o,--output", args->output, "output PNG file (written atomically)")->required();
    cmd->add_option("--timing", args->timing, "render N extra frames and print median ms per pass and total")
        ->check(CLI::Range(0, 100000));
    cmd->add_option("--save-style", args->save_style,
                    "also write the style used (with every --set applied) to a .toml file");
    return [args] { return run_render(*args); };
}

}  // namespace inkshade::cli
