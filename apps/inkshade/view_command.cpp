// `inkshade view [MODEL]`: the interactive viewer (apps/viewer), with the camera, light and style
// options of `render`, plus scripting for tests and screenshots.
#include "commands.hpp"
#include "inkshade/error.hpp"
#include "scene_options.hpp"
#include "viewer/viewer.hpp"

namespace inkshade::cli {

Command add_view_command(CLI::App& app) {
    struct Args {
        SceneOptions scene;
        std::string script, screenshot;
        int frames = 0;
        bool hide_gui = false;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("view", "open a window to look at a model and tune a style");
    args->scene.add_to(*cmd, kView, /*model=*/true, /*model_required=*/false);
    cmd->add_option("--script", args->script, "run the commands of FILE, one per frame (docs/viewer.md), then exit");
    cmd->add_option("--screenshot", args->screenshot, "with --frames: save the window to this PNG at the end");
    cmd->add_option("--frames", args->frames, "exit after N frames")->check(CLI::Range(0, 1000000));
    cmd->add_flag("--hide-gui", args->hide_gui, "start with the panels hidden (H toggles)");
    return [args, cmd] {
        if (!args->screenshot.empty() && args->frames == 0)
            throw InputError("--screenshot needs --frames N (the frame to save)");
        viewer::ViewerOptions o;
        o.scene = make_scene(args->scene.to_request(*cmd));
        o.gui = !args->hide_gui;
        o.script = args->script;
        o.screenshot = args->screenshot;
        o.frames = args->frames;
        return viewer::run_viewer(o);
    };
}

}  // namespace inkshade::cli
