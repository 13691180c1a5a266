// `inkshade demo`: the built-in demo of `make run` — the Utah teapot in every built-in style
// (every shading model, the cel presets and line styles, the debug views), one PNG each plus a
// labelled contact sheet, and the SVG line drawing of the same view.
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

#include "commands.hpp"
#include "inkshade/contact_sheet.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/line_drawing.hpp"
#include "inkshade/scene.hpp"

namespace inkshade::cli {

namespace {

// The tiles that need another background than their style's for the model to show. three.js
// draws a MeshBasicMaterial unlit, all in its colour (white by default), over the clear colour
// of its WebGLRenderer, black: on the style's white the teapot would be white on white.
std::optional<glm::vec4> tile_background(const std::string& style) {
    static const std::map<std::string, glm::vec4> backgrounds = {{"threejs-basic", {0.0f, 0.0f, 0.0f, 1.0f}}};
    const auto it = backgrounds.find(style);
    return it == backgrounds.end() ? std::nullopt : std::optional(it->second);
}

}  // namespace

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
        if (!std::filesystem::is_directory(args->out)) throw InputError(args->out + ": cannot create output folder");
        SceneRequest request;
        request.model = args->model;
        request.size = {args->size, args->size};
        const Mesh mesh = load_mesh(request.model);
        const BoundingBox box = mesh.bounds();
        Renderer renderer;
        renderer.set_mesh(mesh);
        std::vector<LabelledImage> tiles, debug_tiles;
        for (const std::string& name : builtin_style_names()) {
            request.style = name;
            request.background = tile_background(name);
            const Scene scene = make_scene(request);
            const Camera camera = scene.frame(mesh);
            Image image = render_scene(renderer, scene, camera, scene.light(box, camera));
            const std::string path = (std::filesystem::path(args->out) / (name + ".png")).string();
            write_png(path, image);
            std::printf("  %s\n", path.c_str());
            const bool debug = shading_model(scene.style.shading.model).debug_view;
            (debug ? debug_tiles : tiles).push_back({debug ? name + " (debug)" : name, std::move(image)});
        }
        for (auto& t : debug_tiles) tiles.push_back(std::move(t));
        // The vector line drawing of the same view: what `inkshade lines MODEL` writes.
        {
            request.style.clear();
            request.background.reset();
            request.outputs = {.image = false, .line_drawing = true};
            const Scene scene = make_scene(request);
            LineExtractor extractor(mesh);
            const std::string svg = (std::filesystem::path(args->out) / "lines.svg").string();
            write_svg(svg, draw_scene_lines(extractor, scene, scene.frame(mesh)), scene.style.background);
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
