// inkshade: non-photorealistic rendering of triangle meshes from the command line.
#include <malloc.h>

#include <cstdio>
#include <iostream>
#include <map>

#include "commands.hpp"
#include "inkshade/error.hpp"
#include "inkshade/version.hpp"

namespace {

// One line on stderr, as every error of the CLI is reported.
void print_error(const std::string& message) {
    std::string line = message;
    for (char& c : line)
        if (c == '\n' || c == '\r') c = ' ';
    std::cerr << "inkshade: " << line << "\n";
}

}  // namespace

int main(int argc, char** argv) {
    // llvmpipe allocates and frees large per-draw buffers every frame; glibc would mmap each
    // one afresh and page-fault it in again. Keeping them in the heap halved the per-frame
    // time of a 1M-triangle render here (docs/benchmarks.md).
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    CLI::App app{"inkshade: non-photorealistic rendering of triangle meshes (toon, technical, lines)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("inkshade ") + inkshade::kVersion);
    app.footer("Exit status: 0 success, 1 rendering or runtime failure, 2 bad input or bad usage.");
    std::map<CLI::App*, inkshade::cli::Command> commands;
    for (auto add :
         {inkshade::cli::add_render_command, inkshade::cli::add_lines_command, inkshade::cli::add_view_command,
          inkshade::cli::add_info_command, inkshade::cli::add_styles_command, inkshade::cli::add_demo_command,
          inkshade::cli::add_batch_command}) {
        size_t before = app.get_subcommands({}).size();
        auto run = add(app);
        commands[app.get_subcommands({})[before]] = run;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        print_error(std::string(e.what()) + " (see inkshade --help)");
        return 2;
    }
    try {
        for (auto& [sub, run] : commands)
            if (sub->parsed()) return run();
        return 2;
    } catch (const inkshade::InputError& e) {
        print_error(e.what());
        return 2;
    } catch (const inkshade::RuntimeError& e) {
        print_error(e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        print_error("out of memory");
        return 1;
    } catch (const std::exception& e) {
        print_error(e.what());
        return 1;
    }
}
