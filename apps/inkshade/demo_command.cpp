// `inkshade demo`: the built-in demo of `make run` — the Utah teapot in every built-in style
// (every shading model, the seed presets and line styles, the debug views), one PNG each plus a
// labelled contact sheet, and the SVG line drawing of the same view.
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "inkshade/contact_sheet.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/renderer.hpp"
#include "inkshade/style.hpp"

namespace inkshade::cli {

Command add_demo_command(CLI::App& app) {
    struct Args {
        std::string out = "out";
        std::string model = "builtin:teapot";
        int size = 512;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("demo", "render the built-in demo (every built-in style) into a folder");
    cmd->add_option("--out", args->out, "output folder (created)")->capture_default_str();
    cmd->add_option("--model", args->model, "model to render")->capture_default_str();
    cmd->add_option("--size", args->size, "tile size in pixels")->check(CLI::Range(16, 4096))->capture_default_str();
    return [args] {
        std::error_code ec;
        std::filesystem::create_directories(args->out, ec);
        if (!std::filesystem::is_directory(args->out))
            throw InputError(args->out + ": cannot create output folder");
        const Mesh mesh = load_mesh(args->model);
        RenderOptions options;
        options.width = options.height = args->size;
        const Camera camera = frame_camera(mesh.bounds(), {}, 1.0f);
        Renderer renderer;
        renderer.set_mesh(mesh);
        std::vector<LabelledImage> tiles, debug_tiles;
        for (const std::string& name : builtin_style_names()) {
            const Style style = load_style(name);
            Light light = default_light(mesh.bounds(), camera);
            apply_style_light(style, light);
            options.background = style.background;
            Image image = renderer.render(camera, light, style.shading, style.lines, options);
            const std::string path = (std::filesystem::path(args->out) / (name + ".png")).string();
            write_png(path, image);
            std::printf("  %s\n", path.c_str());
            const bool debug = shading_model(style.shading.model).debug_view;
            (debug ? debug_tiles : tiles).push_back({debug ? name + " (debug)" : name, std::move(image)});
        }
        for (auto& t : debug_tiles) tiles.push_back(std::move(t));
        // The vector line drawing of the same view (what `inkshade lines` writes).
        {
            LineExtractor extractor(mesh);
            std::vector<LineSettings> vector_lines;
            for (const char* type : {"contour", "suggestive", "crease", "border"}) vector_lines.push_back({type, {}});
            const std::string svg = (std::filesystem::path(args->out) / "lines.svg").string();
            write_svg(svg, extractor.draw(camera, args->size, args->size, vector_lines), glm::vec4(1.0f));
            std::printf("  %s\n", svg.c_str());
        }
        const std::string sheet = (std::filesystem::path(args->out) / "contact_sheet.png").string();
        write_png(sheet, contact_sheet(tiles, 5));
        std::printf("demo: %zu images and the contact sheet %s (renderer: %s)\n", tiles.size(), sheet.c_str(),
                    renderer.gl_renderer().c_str());
        return 0;
    };
}

}  // namespace inkshade::cli
