// `inkshade lines MODEL -o out.svg`: the object-space line drawing of a model (contours,
// suggestive contours, creases, borders, ...) with hidden lines removed, as layered SVG.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "commands.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/line_drawing.hpp"
#include "io/atomic_file.hpp"
#include "output_path.hpp"
#include "scene_options.hpp"
#include "timing_report.hpp"

namespace inkshade::cli {

namespace {

// Drawn when neither --lines nor the style names an object-space type (SPEC §3 vector output).
const std::vector<std::string> kDefaultLines = {"contour", "suggestive", "crease", "border"};


struct LinesArgs {
    SceneOptions scene;
    std::string output;
    std::string lines;  // --lines a,b,c
    std::string lines_json;
    bool hidden = false;
    int timing = 0;
};

// The object-space line types to draw, in order, with the style's parameters where it has them.
std::vector<LineSettings> select_lines(const Style& style, const std::string& option) {
    auto from_style = [&](const std::string& name) {
        for (const LineSettings& l : style.lines)
            if (l.type == name) return l;
        return LineSettings{name, {}};
    };
    std::vector<LineSettings> out;
    if (option.empty()) {
        for (const LineSettings& l : style.lines)
            if (line_type(l.type).space == LineSpace::Object) out.push_back(l);
        if (out.empty())
            for (const std::string& name : kDefaultLines) out.push_back(from_style(name));
        return out;
    }
    std::stringstream ss(option);
    std::string name;
    while (std::getline(ss, name, ',')) {
        if (name.empty()) throw InputError("--lines: empty line type name in '" + option + "'");
        const LineType& type = line_type(name);  // InputError names the choices
        if (type.space != LineSpace::Object) {
            std::string names;
            for (const LineType* t : line_types())
                if (t->space == LineSpace::Object) names += (names.empty() ? "" : ", ") + t->name;
            throw InputError("--lines: '" + name + "' is drawn in the image by `inkshade render`, not as vector " +
                             "lines (choose " + names + ")");
        }
        for (const LineSettings& l : out)
            if (l.type == name) throw InputError("--lines: '" + name + "' is listed twice");
        out.push_back(from_style(name));
    }
    if (out.empty()) throw InputError("--lines: no line type given");
    return out;
}

void print_timing(const LinesArgs& args, size_t triangles, const LineDrawing& drawing, const Style& style,
                  const std::vector<LineTiming>& setup, LineExtractor& extractor, const Camera& camera,
                  double load_ms) {
    std::map<std::string, std::vector<double>> per_stage;
    std::vector<std::string> order;
    std::vector<double> totals;
    for (int i = 0; i < args.timing; ++i) {
        std::vector<LineTiming> timings;
        const auto start = std::chrono::steady_clock::now();
        extractor.draw(camera, drawing.width, drawing.height, style.lines, &timings);
        totals.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        for (const auto& t : timings) {
            if (!per_stage.count(t.stage)) order.push_back(t.stage);
            per_stage[t.stage].push_back(t.milliseconds);
        }
    }
    std::string names;
    for (const LineSettings& l : style.lines) names += (names.empty() ? "" : ",") + l.type;
    size_t paths = 0;
    for (const LineLayer& l : drawing.layers) paths += l.visible.size() + l.hidden.size();
    std::printf("timing: lines %s, %zu triangles, %dx%d, %zu paths, %d views\n", names.c_str(),
                triangles, drawing.width, drawing.height, paths, args.timing);
    for (const auto& stage : order)
        std::printf("  %-10s median %8.2f ms\n", stage.c_str(), median(per_stage[stage]));
    std::printf("  %-10s median %8.2f ms\n", "total", median(totals));
    std::string once;
    for (const LineTiming& t : setup)
        if (!per_stage.count(t.stage)) {
            char buf[96];
            std::snprintf(buf, sizeof buf, "%s%s %.0f ms", once.empty() ? "" : ", ", t.stage.c_str(), t.milliseconds);
            once += buf;
        }
    std::printf("  once per mesh: %s; load %.0f ms, peak RSS %.0f MiB\n", once.empty() ? "none" : once.c_str(),
                load_ms, peak_rss_mib());
}

int run_lines(const LinesArgs& args) {
    check_output_path("-o", args.output);
    if (!args.lines_json.empty()) check_output_path("--lines-json", args.lines_json);
    Style style = args.scene.loaded_style();
    style.lines = select_lines(style, args.lines);
    if (args.hidden)
        for (LineSettings& l : style.lines) l.params["hidden"] = {1.0f};
    args.scene.apply_overrides(style);  // --set TYPE.param=value wins over --hidden
    const glm::ivec2 size = args.scene.image_size();

    const auto load_start = std::chrono::steady_clock::now();
    Mesh mesh = load_mesh(args.scene.model);
    const double load_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - load_start).count();
    const Camera camera = args.scene.camera(mesh.bounds(), float(size.x) / float(size.y));

    const size_t triangles = mesh.triangle_count();
    LineExtractor extractor(std::move(mesh));  // takes the mesh's arrays: no copy
    std::vector<LineTiming> first;
    const LineDrawing drawing = extractor.draw(camera, size.x, size.y, style.lines, &first);
    if (args.timing > 0) print_timing(args, triangles, drawing, style, first, extractor, camera, load_ms);
    if (args.lines_json.empty()) {
        write_svg(args.output, drawing, style.background);
        return 0;
    }
    // Both files or neither: the JSON is removed again if the SVG cannot be written.
    io::write_file_atomic(args.lines_json, format_lines_json(drawing));
    try {
        write_svg(args.output, drawing, style.background);
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
    return [args] { return run_lines(*args); };
}

}  // namespace inkshade::cli
