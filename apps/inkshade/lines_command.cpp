// `inkshade lines MODEL -o out.svg`: the object-space line drawing of a model (contours,
// suggestive contours, creases, borders, ...) with hidden lines removed, as layered SVG, or as
// a PNG or JPEG image drawn by the renderer's stroke pass (the pixels `render` gives the lines).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>

#include "commands.hpp"
#include "core/name_suggestion.hpp"
#include "image_output.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/renderer.hpp"
#include "inkshade/scene.hpp"
#include "io/atomic_file.hpp"
#include "io/text_scanner.hpp"
#include "mesh_export.hpp"
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
    bool svg_polylines = false;  // --svg-polylines: points, not fitted Béziers
    int timing = 0;
    ImageOutputOptions image;  // --quality, --bit-depth
};

void print_timing(const LinesArgs& args, size_t triangles, const LineDrawing& drawing, const Scene& scene,
                  const std::vector<LineTiming>& setup, LineExtractor& extractor, const Camera& camera,
                  double load_ms) {
    std::map<std::string, std::vector<double>> per_stage;
    std::vector<std::string> order;
    std::vector<double> totals;
    // With a `coherence` layer the views are one sequence, so the `coherence` stage (matching
    // each view's strokes to the previous view's) is timed too.
    bool coherent = false;
    for (const LineSettings& l : scene.vector_lines) {
        const auto it = l.params.find("coherence");
        coherent |= it != l.params.end() && !it->second.empty() && it->second[0] != 0.0f;
    }
    StrokeSequence sequence;
    for (int i = 0; i < args.timing; ++i) {
        std::vector<LineTiming> timings;
        const auto start = std::chrono::steady_clock::now();
        draw_scene_lines(extractor, scene, camera, &timings, coherent ? &sequence : nullptr);
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
    if (lower_ascii(std::filesystem::path(args.output).extension().string()) == ".svg") {
        // Formatting the SVG text (Bézier fitting included), apart from the views above.
        std::vector<double> svg_ms;
        const SvgOptions svg{.polylines = args.svg_polylines};
        for (int i = 0; i < args.timing; ++i) {
            const auto start = std::chrono::steady_clock::now();
            const std::string text = format_svg(drawing, scene.style.background, svg);
            svg_ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
            if (text.empty()) std::printf("empty SVG\n");
        }
        std::printf("  %-10s median %8.2f ms (%s)\n", "svg", median(svg_ms),
                    args.svg_polylines ? "polylines" : "Bezier fit");
    }
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

int run_lines(LinesArgs& args, const CLI::App& cmd) {
    SceneRequest request = args.scene.to_request(cmd);
    args.image.take_bit_depth(cmd, request);
    const std::optional<OcclusionLevels> levels = request.occlusion_levels;
    // Every output checked before any work: a run that fails leaves no file.
    check_output_path("-o", args.output);
    const std::string ext = lower_ascii(std::filesystem::path(args.output).extension().string());
    std::optional<ImageOutput> image_file;
    if (ext == ".svg") {
        refuse_image_options(args.image);
    } else if (ext == ".png" || ext == ".jpg" || ext == ".jpeg") {
        image_file = image_output(args.output, args.image);
        if (args.svg_polylines) throw InputError("--svg-polylines: only for .svg output");
        if (args.hidden) throw InputError("--hidden: hidden lines are drawn (dashed) in SVG only; write .svg");
        if (levels && levels->max > 0)
            throw InputError("--occlusion-levels: hidden levels are drawn (dashed) in SVG only; write .svg");
    } else {
        throw InputError(args.output, "cannot write " +
                                          (ext.empty() ? std::string("line drawings without an extension")
                                                       : io::quote_token(ext) + " line drawings") +
                                          " (write .svg, .png, .jpg or .jpeg)");
    }
    if (!args.lines_json.empty()) check_output_path("--lines-json", args.lines_json);
    if (args.lines_json.empty() && request.lines_json_detail != LinesJsonDetail::Basic)
        throw InputError("--lines-json-detail: it says what --lines-json writes; give --lines-json FILE too");
    MeshExport exported(request);
    request.outputs = {.image = false, .line_drawing = true};
    request.vector_lines = split_names(args.lines);
    request.hidden = args.hidden;
    Scene scene = make_scene(request);
    if (image_file) check_background(*image_file, scene.options.background);
    // The GL context before the work, so a machine without one fails at once.
    std::optional<Renderer> renderer;
    if (image_file) renderer.emplace();

    double load_ms = 0.0;
    Mesh mesh = load_scene_model(scene, load_ms);
    const Camera camera = scene.frame(mesh);
    exported.keep(mesh);

    const size_t triangles = mesh.triangle_count();
    LineExtractor extractor(std::move(mesh));  // takes the mesh's arrays: no copy
    std::vector<LineTiming> first;
    const LineDrawing drawing = draw_scene_lines(extractor, scene, camera, &first);
    if (args.timing > 0) print_timing(args, triangles, drawing, scene, first, extractor, camera, load_ms);
    Image image;
    if (renderer) image = renderer->draw_lines(drawing, scene.options);
    const auto write_output = [&] {
        if (image_file)
            write_image(*image_file, image);
        else
            write_svg(args.output, drawing, scene.style.background, SvgOptions{.polylines = args.svg_polylines});
    };
    if (args.lines_json.empty()) {
        write_output();
        exported.write({args.output});
        return 0;
    }
    // Both files or neither: the JSON is removed again if the drawing cannot be written.
    io::write_file_atomic(args.lines_json, format_lines_json(drawing, scene.lines_json_detail));
    try {
        write_output();
    } catch (...) {
        std::error_code ec;
        std::filesystem::remove(args.lines_json, ec);
        throw;
    }
    exported.write({args.output, args.lines_json});
    return 0;
}

}  // namespace

Command add_lines_command(CLI::App& app) {
    auto args = std::make_shared<LinesArgs>();
    CLI::App* cmd =
        app.add_subcommand("lines", "draw a model's contours, creases, ... as a layered SVG or a PNG/JPEG image");
    args->scene.add_to(*cmd, kLines);
    cmd->add_option("-o,--output", args->output,
                    "output file by its extension: .svg (layers, hidden lines), or .png or .jpg/.jpeg drawn by the "
                    "renderer's strokes (written atomically)")
        ->required();
    cmd->add_option("--lines", args->lines,
                    "object-space line types to draw, comma-separated (default: the style's, else "
                    "contour,suggestive,crease,border)");
    cmd->add_option("--lines-json", args->lines_json, "also write the polylines as JSON (docs/lines.md)");
    cmd->add_flag("--hidden", args->hidden,
                  "also draw every hidden line, dashed, in layers TYPE-hidden-N by occlusion level N (SVG only)");
    cmd->add_flag("--svg-polylines", args->svg_polylines,
                  "write each path's points as a polyline instead of cubic Beziers fitted within 0.2 px");
    args->image.add_to(*cmd);
    cmd->add_option("--timing", args->timing, "extract N extra views and print median ms per stage and total")
        ->check(CLI::Range(0, 100000));
    return [args, cmd] { return run_lines(*args, *cmd); };
}

}  // namespace inkshade::cli
