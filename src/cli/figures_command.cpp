// `glideshadows figures`: the articles' figures rendered by our code, with their checks and an
// index page (figures/figures.h).
#include "cli/commands.h"
#include "figures/figures.h"

#include <cstdio>
#include <memory>
#include <string>

namespace gs::cli {

Command add_figures_command(CLI::App &app) {
  struct FiguresOptions {
    std::string out = "out/figures", only;
  };
  auto o = std::make_shared<FiguresOptions>();
  CLI::App *figures = app.add_subcommand("figures", "reproduce the articles' figures as PNGs with checks and an index page");
  figures->add_option("--out", o->out, "directory for the PNGs and index.html")->capture_default_str();
  figures->add_option("--only", o->only,
                      "comma-separated figures: names such as nguyen-7, sgi-3, everitt-5, or bare numbers for Nguyen's");
  return {figures, [o] { return run_figures(o->out, o->only, stdout); }};
}

}  // namespace gs::cli
