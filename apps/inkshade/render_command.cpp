// `inkshade render MODEL -o out.png`: one image of a model with a shading model.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "commands.hpp"
#include "image_output.hpp"
#include "inkshade/aov.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/scene.hpp"
#include "mesh_export.hpp"
#include "mesh_warnings.hpp"
#include "output_path.hpp"
#include "scene_options.hpp"
#include "timing_report.hpp"

namespace inkshade::cli {

namespace {

std::vector<std::string> line_masks_of(const Scene& scene) {
    std::vector<std::string> names;
    for (const LineSettings& l : scene.style.lines) names.push_back(line_mask_name(l.lineset, l.type));
    return names;
}

std::vector<std::string> line_sets_of(const Scene& scene) {
    std::vector<std::string> names = line_set_names(scene.style.lines);
    for (std::string& n : names)
        if (n.empty()) n = kDefaultLineSet;
    return names;
}

struct RenderArgs {
    SceneOptions scene;
    std::string output;
    int timing = 0;
    std::string save_style;
    ImageOutputOptions image;  // --quality, --bit-depth
    std::string scene_file;    // --scene
    std::string lines;         // --lines a,b: line types added to the style
};

int run_render(RenderArgs& args, const CLI::App& cmd) {
    // Every output checked before any work: a run that fails leaves no file.
    check_output_path("-o", args.output);
    SceneRequest request = args.scene.to_request(cmd, args.scene_file);
    args.image.take_bit_depth(cmd, request);
    const ImageOutput output = image_output(args.output, args.image);
    if (!args.save_style.empty()) check_output_path("--save-style", args.save_style);
    request.added_lines = split_names(args.lines).value_or(std::vector<std::string>{});
    MeshExport exported(request);
    Scene scene = make_scene(request);
    if (scene.model.empty()) throw InputError("MODEL is required (a mesh file or builtin:NAME), or --scene FILE");
    check_background(output, scene.options.background);
    const RenderOptions& options = scene.options;
    double load_ms = 0.0;
    Mesh mesh = load_scene_model(scene, load_ms);
    exported.keep(mesh);
    const BoundingBox box = mesh.bounds();
    const Camera camera = scene.frame(mesh);
    const Light light = scene.light(box, camera);

    const size_t triangles = mesh.triangle_count();
    Renderer renderer;
    // The renderer keeps what lines need (no second copy). One image: object-space lines are
    // extracted before the GL upload and their data freed first (MeshUse::OneFrame).
    // Line masks render a frame a line type: the line data is kept for them (ManyFrames).
    const bool many_frames = args.timing > 0 || scene.aovs.contains(Aov::Lines) || scene.aovs.contains(Aov::LineSets);
    renderer.set_mesh(std::move(mesh), many_frames ? MeshUse::ManyFrames : MeshUse::OneFrame);
    AovImages aovs;
    Image image = scene.aovs.empty() ? render_scene(renderer, scene, camera, light)
                                     : render_scene(renderer, scene, camera, light, aovs);
    if (args.timing > 0) {
        // Wall time (each pass finished before and after) and GPU time (timestamp queries). On a
        // GPU the second leaves out the driver's CPU work; llvmpipe stamps some passes before
        // its rasterizer has run them (the hull reads ~0.3 ms), so use wall time there.
        std::map<std::string, std::vector<double>> per_pass, per_pass_gpu;
        std::vector<std::string> order;
        std::vector<double> totals, gpu_totals;
        for (int i = 0; i < args.timing; ++i) {
            std::vector<PassTiming> timings;
            auto start = std::chrono::steady_clock::now();
            // With the AOVs asked for: their passes are timed too (the files are not written).
            image = scene.aovs.empty() ? render_scene(renderer, scene, camera, light, &timings)
                                       : render_scene(renderer, scene, camera, light, aovs, &timings);
            totals.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            double gpu = 0.0;
            for (const auto& t : timings) {
                if (!per_pass.count(t.pass)) order.push_back(t.pass);
                per_pass[t.pass].push_back(t.milliseconds);
                per_pass_gpu[t.pass].push_back(t.gpu_milliseconds);
                gpu += t.gpu_milliseconds;
            }
            gpu_totals.push_back(gpu);
        }
        std::printf("timing: %s, %zu triangles, %dx%d, %d samples, %d frames on %s\n",
                    scene.style.shading.model.c_str(), triangles, options.width, options.height, options.samples,
                    args.timing, renderer.gl_renderer().c_str());
        for (const auto& pass : order)
            std::printf("  %-10s median %8.2f ms  gpu %8.3f ms\n", pass.c_str(), median(per_pass[pass]),
                        median(per_pass_gpu[pass]));
        std::printf("  %-10s median %8.2f ms  gpu %8.3f ms\n", "total", median(totals), median(gpu_totals));
        std::printf("  load %.0f ms, peak RSS %.0f MiB\n", load_ms, peak_rss_mib());
    }
    write_image(output, image);
    try {  // every file or none: the image and the AOVs beside it are removed when a later file fails
        if (!scene.aovs.empty()) write_aov_files(args.output, scene.aovs, aovs, camera_record(scene, camera, box));
        if (!args.save_style.empty()) save_style(args.save_style, scene.style);
        exported.write({});
    } catch (...) {
        std::error_code ec;
        std::filesystem::remove(args.output, ec);
        for (const std::string& name :
             aov_file_names(args.output, scene.aovs, line_masks_of(scene), line_sets_of(scene)))
            std::filesystem::remove(std::filesystem::path(args.output).parent_path() / name, ec);
        throw;
    }
    return 0;
}

}  // namespace

Command add_render_command(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "render a model to a PNG or JPEG image");
    args->scene.add_to(*cmd, kRender, /*model=*/true, /*model_required=*/false);  // --scene may name it
    cmd->add_option("-o,--output", args->output,
                    "output image, .png or .jpg/.jpeg by its extension (written atomically)")
        ->required();
    args->image.add_to(*cmd);
    cmd->add_option("--timing", args->timing, "render N extra frames (their AOVs too) and print median ms per pass and total")
        ->check(CLI::Range(0, 100000));
    cmd->add_option("--lines", args->lines,
                    "line types added to the style, comma-separated: raster (hull, rim-contour, edges, ...) or "
                    "object-space (contour, suggestive, crease, ...); --set TYPE.param=value then reaches them");
    cmd->add_option("--save-style", args->save_style,
                    "also write the style used (with every --set applied) to a .toml file");
    cmd->add_option("--scene", args->scene_file,
                    "three.js-like scene JSON (mesh, material, lights, camera, background; docs/threejs.md); "
                    "options given here override its values");
    return [args, cmd] { return run_render(*args, *cmd); };
}

}  // namespace inkshade::cli
