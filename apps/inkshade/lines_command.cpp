// `inkshade lines MODEL -o out.svg`: the object-space line drawing of a model (contours,
// suggestive contours, creases, borders, ...) with hidden lines removed, as layered SVG.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>

#include "commands.hpp"
#include "core/name_suggestion.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/scene.hpp"
#include "io/atomic_file.hpp"
#include "mesh_warnings.hpp"
#include "output_path.hpp"
#include "scene_options.hpp"
#include "timing_report.hpp"

namespace inkshade::cli {

namespace {

struct LinesArgs {
    SceneOptions scene;
    std::string output;
    std::string lines;  // --lines a,b,c
    std::string lines_json;
    bool hidden = false;
    int timing = 0;
};

void print_timing(const LinesArgs& args, size_t triangles, const LineDrawing& drawing, const Scene& scene,
                  const std::vector<LineTiming>& setup, LineExtractor& extractor, const Camera& camera,
                  double load_ms) {
    std::map<std::string, std::vector<double>> per_stage;
    std::vector<std::string> order;
    std::vector<double> totals;
    for (int i = 0; i < args.timing; ++i) {
        std::vector<LineTiming> timings;
        const auto start = std::chrono::steady_clock::now();
        draw_scene_lines(extractor, scene, camera, &timings);
        totals.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        for (const auto& t : timings) {
            if (!per_stage.count(t.stage)) order.push_back(t.stage);
            per_stage[t.stage].push_back(t.milliseconds);
        }
    }
    std::string names;
    for (const LineSettings& l : scene.vector_lines) names += (names.empty() ? "" : ",") + l.type;
    size_t paths = 0;
    for (const LineLayer& l : drawing.layers) paths += l.visible.size() + l.hidden.size();
    std::printf("timing: lines %s, %zu triangles, %dx%d, %zu paths, %d views\n", names.c_str(), triangles,
                drawing.width, drawing.height, paths, args.timing);
    for (const auto& stage : order) std::printf("  %-10s median %8.2f ms\n", stage.c_str(), median(per_stage[stage]));
    std::printf("  %-10s median %8.2f ms\n", "total", median(totals));
    std::string once;
    for (const LineTiming& t : setup)
        if (!per_stage.count(t.stage)) {
            char buf[96];
            std::snprintf(buf, sizeof buf, "%s%s %.0f ms", once.empty() ? "" : ", ", t.stage.c_str(), t.milliseconds);
            once += buf;
        }
    std::printf("  once per mesh: %s; load %.0f ms, peak RSS %.0f MiB\n", once.empty() ? "none" : once.c_str(), load_ms,
                peak_rss_mib());
}

int run_lines(const LinesArgs& args, const CLI::App& cmd) {
    check_output_path("-o", args.output);
    const std::string ext = lower_ascii(std::filesystem::path(args.output).extension().string());
    // Until line drawings are rasterised, anything but SVG text would land in a misnamed file.
    if (ext != ".svg") throw InputError(args.output + ": `inkshade lines` writes SVG: name the output .svg");
    if (!args.lines_json.empty()) check_output_path("--lines-json", args.lines_json);
    SceneRequest request = args.scene.to_request(cmd);
    request.outputs = {.image = false, .line_drawing = true};
    request.vector_lines = split_names(args.lines);
    request.hidden = args.hidden;
    Scene scene = make_scene(request);

    const auto load_start = std::chrono::steady_clock::now();
    Mesh mesh = load_mesh(scene.model, scene.load_options());
    print_mesh_warnings(mesh);
    print_warnings(scene.apply_file_scene(mesh));
    const double load_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - load_start).count();
    const Camera camera = scene.frame(mesh.bounds());

    const size_t triangles = mesh.triangle_count();
    LineExtractor extractor(std::move(mesh));  // takes the mesh's arrays: no copy
    std::vector<LineTiming> first;
    const LineDrawing drawing = draw_scene_lines(extractor, scene, camera, &first);
    if (args.timing > 0) print_timing(args, triangles, drawing, scene, first, extractor, camera, load_ms);
    if (args.lines_json.empty()) {
        write_svg(args.output, drawing, scene.style.background);
        return 0;
    }
    // Both files or neither: the JSON is removed again if the SVG cannot be written.
    io::write_file_atomic(args.lines_json, format_lines_json(drawing));
    try {
        write_svg(args.output, drawing, scene.style.background);
    } catch (...) {
        std::error_code ec;
        std::filesystem::remove(args.lines_json, ec);
        throw;
    }
    return 0;
}

}  // namespace

Command add_lines_command(CLI::App& app) {
    auto args = std::make_shared<LinesArgs>();
    CLI::App* cmd = app.add_subcommand("lines", "draw a model's contours, creases, ... as a layered SVG");
    args->scene.add_to(*cmd);
    cmd->add_option("-o,--output", args->output, "output SVG file (written atomically)")->required();
    cmd->add_option("--lines", args->lines,
                    "object-space line types to draw, comma-separated (default: the style's, else "
                    "contour,suggestive,crease,border)");
    cmd->add_option("--lines-json", args->lines_json, "also write the polylines as JSON (docs/lines.md)");
    cmd->add_flag("--hidden", args->hidden, "also draw hidden lines, dashed, in layers TYPE-hidden");
    cmd->add_option("--timing", args->timing, "extract N extra views and print median ms per stage and total")
        ->check(CLI::Range(0, 100000));
    return [args, cmd] { return run_lines(*args, *cmd); };
}

}  // namespace inkshade::cli
