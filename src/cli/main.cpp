// glideshadows: the command-line tool. It only wires the subcommands (commands.h); each one's
// options and work are in its own file. Every subcommand has --help. Exit status: 0 success,
// 1 bad input or a failed run (each subcommand's), 2 a bad command line.
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
  // Exit status (docs/cli.md): 2 for a command line CLI11 refuses (an unknown option or value,
  // a missing argument), not CLI11's own codes (105, 106, ...); 0 for --help.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError &e) {
    return app.exit(e) == static_cast<int>(CLI::ExitCodes::Success) ? 0 : 2;
  }
  for (const gs::cli::Command &command : commands) {
    if (command.app->parsed()) return command.run();
  }
  return 2;
}
