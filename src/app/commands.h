#pragma once
#include <CLI/CLI.hpp>

#include <functional>

namespace hipr::app {

// Each subcommand registers itself and returns the action to run when it was chosen.
struct Command {
  CLI::App* subcommand;
  std::function<int()> run;
};

Command add_render_command(CLI::App& app);
Command add_info_command(CLI::App& app);
Command add_replay_command(CLI::App& app);
Command add_bench_command(CLI::App& app);
Command add_view_command(CLI::App& app);
Command add_compare_command(CLI::App& app);

}  // namespace hipr::app
