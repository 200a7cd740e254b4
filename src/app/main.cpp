// hipr: entry point. Every error ends here as one line on stderr and an exit code:
// 0 ok, 2 bad input (file, flag, scene), 1 internal.
#include <CLI/CLI.hpp>

#include <cstdio>

#include "app/commands.h"
#include "core/error.h"
#include "core/log.h"

int main(int argc, char** argv) {
  CLI::App app{"hipr: a Vulkan path tracer that re-renders first what a scene edit changes"};
  app.require_subcommand(1);
  const hipr::app::Command commands[] = {
      hipr::app::add_render_command(app), hipr::app::add_info_command(app),
      hipr::app::add_replay_command(app), hipr::app::add_bench_command(app),
      hipr::app::add_view_command(app),   hipr::app::add_compare_command(app),
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "hipr: error: %s (see hipr --help)\n",
                 hipr::log::printable_line(e.what()).c_str());
    return hipr::kExitBadInput;
  }

  try {
    for (const hipr::app::Command& command : commands)
      if (command.subcommand->parsed()) return command.run();
    return hipr::kExitBadInput;
  } catch (const hipr::InputError& e) {
    std::fprintf(stderr, "hipr: error: %s\n", hipr::log::printable_line(e.what()).c_str());
    return hipr::kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hipr: internal error: %s\n", hipr::log::printable_line(e.what()).c_str());
    return hipr::kExitInternal;
  }
}
