// `inkshade demo`: the built-in demo of `make run` — the Utah teapot in every shading model
// and debug view, one PNG each plus a labelled contact sheet.
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "inkshade/contact_sheet.hpp"
#include "inkshade/error.hpp"
#include "inkshade/io.hpp"
#include "inkshade/renderer.hpp"

namespace inkshade::cli {

Command add_demo_command(CLI::App& app) {
    struct Args {
        std::string out = "out";
        std::string model = "builtin:teapot";
        int size = 512;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("demo", "render the built-in demo (every shading model) into a folder");
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
        const Light light = default_light(mesh.bounds(), camera);
        Renderer renderer;
        renderer.set_mesh(mesh);
        std::vector<LabelledImage> tiles;
        for (const ShadingModel* model : shading_models()) {
            ShadingSelection shading;
            shading.model = model->name;
            shading.base_color = glm::vec3(0.95f, 0.75f, 0.55f);  // warm clay, shows the light well
            Image image = renderer.render(camera, light, shading, options);
            const std::string path = (std::filesystem::path(args->out) / (model->name + ".png")).string();
            write_png(path, image);
            std::printf("  %s\n", path.c_str());
            tiles.push_back({model->debug_view ? model->name + " (debug)" : model->name, std::move(image)});
        }
        const std::string sheet = (std::filesystem::path(args->out) / "contact_sheet.png").string();
        write_png(sheet, contact_sheet(tiles, 5));
        std::printf("demo: %zu images and the contact sheet %s (renderer: %s)\n", tiles.size(), sheet.c_str(),
                    renderer.gl_renderer().c_str());
        return 0;
    };
}

}  // namespace inkshade::cli
