// Subcommands of the inkshade CLI. Each registers its options on the app and returns the
// function that runs it (exit status: 0 ok, 1 runtime failure, 2 bad input or usage).
#pragma once
#include <functional>

#include <CLI/CLI.hpp>

namespace inkshade::cli {

using Command = std::function<int()>;

Command add_render_command(CLI::App& app);
Command add_lines_command(CLI::App& app);
Command add_view_command(CLI::App& app);
Command add_info_command(CLI::App& app);
Command add_styles_command(CLI::App& app);
Command add_demo_command(CLI::App& app);
Command add_batch_command(CLI::App& app);

}  // namespace inkshade::cli
