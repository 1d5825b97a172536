// The subcommands of `glideshadows`, one file each. Each adds itself to the application with its
// options and returns the function that runs it once the command line is parsed; that function
// returns the process's exit code. `add_demo_command` is the fighting-game demo's (demo/), the
// others are src/cli's own.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace gs::cli {

struct Command {
  CLI::App *app = nullptr;     // the subcommand, owned by the application
  std::function<int()> run;    // runs it with the parsed options
};

Command add_demo_command(CLI::App &app);
Command add_render_command(CLI::App &app);
Command add_truth_command(CLI::App &app);
Command add_compare_command(CLI::App &app);
Command add_bench_command(CLI::App &app);
Command add_figures_command(CLI::App &app);

}  // namespace gs::cli
