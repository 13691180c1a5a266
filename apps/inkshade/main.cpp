// inkshade: non-photorealistic rendering of triangle meshes from the command line.
#include <malloc.h>

#include <cstdio>
#include <iostream>
#include <map>

#include "commands.hpp"
#include "core/name_suggestion.hpp"
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

// " (did you mean 'x'?)" for a parse error caused by a misspelt subcommand or long option, or
// empty. Reads argv, as CLI11 (2.1 in Debian 12) reports the arguments it rejected only as text:
// before the subcommand, a word that is not one is matched against the subcommands and an
// unknown --option against the top-level ones; after it, an unknown --option against the
// subcommand's (there, only when the error message names it).
std::string suggestion(CLI::App& app, int argc, char** argv, const std::string& error) {
    CLI::App* sub = nullptr;
    auto long_options = [](const CLI::App& a) {
        std::vector<std::string> names;
        for (const CLI::Option* o : a.get_options())
            for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
        return names;
    };
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--") break;  // the rest are positional
        if (!sub && arg.rfind("-", 0) != 0) {
            for (CLI::App* s : app.get_subcommands({}))
                if (s->get_name() == arg) sub = s;
            if (sub) continue;
            std::vector<std::string> names;
            for (const CLI::App* s : app.get_subcommands({})) names.push_back(s->get_name());
            return inkshade::did_you_mean(arg, names);  // CLI11 may only say "A subcommand is required"
        }
        if (arg.rfind("--", 0) != 0 || arg.size() < 3) continue;
        const std::string name = arg.substr(0, arg.find('='));
        CLI::App& owner = sub ? *sub : app;
        if (owner.get_option_no_throw(name) || (sub && error.find(name) == std::string::npos)) continue;
        return inkshade::did_you_mean(name, long_options(owner));
    }
    return "";
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
        print_error(std::string(e.what()) + suggestion(app, argc, argv, e.what()) + " (see inkshade --help)");
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
