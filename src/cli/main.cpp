// glideshadows: the command-line tool. It only wires the subcommands (commands.h); each one's
// options and work are in its own file. Every subcommand has --help.
#include "cli/commands.h"

#include <vector>

int main(int argc, char **argv) {
  CLI::App app{"glideshadows: Glide-era projected shadow textures on a Glide 2.x shim, headless"};
  app.require_subcommand(1);
  const std::vector<gs::cli::Command> commands = {
      gs::cli::add_demo_command(app),    gs::cli::add_render_command(app),
      gs::cli::add_truth_command(app),   gs::cli::add_compare_command(app),
      gs::cli::add_bench_command(app),   gs::cli::add_figures_command(app),
  };
  CLI11_PARSE(app, argc, argv);
  for (const gs::cli::Command &command : commands) {
    if (command.app->parsed()) return command.run();
  }
  return 2;
}
