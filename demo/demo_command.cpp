// `glideshadows demo`: the fight headless to PNG frames, optionally a contact sheet and a GIF,
// then the step table; with --window, the fight played in a window instead (fight_window.h).
#include "cli/commands.h"
#include "cli/options.h"
#include "fight_demo.h"
#include "fight_window.h"
#include "media/media.h"

#include <glide.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace gs::cli {
namespace {

struct DemoOptions {
  int frames = 96, fps = 12, shadow_size = 256;
  std::string size = "640x480", out_dir = "out/demo";
  bool gif = false, sheet = false;
  bool window = false, paused = false;
  bool frames_given = false;  // --frames on the command line (the window then stops after them)
  TechniqueChoice choice;
  demo::DemoBeam beam;
};

int run_demo(const DemoOptions &o) {
  if (o.beam.attenuation == "exact" && o.beam.beam.empty()) {
    std::fprintf(stderr, "glideshadows demo: --attenuation exact needs a beam map: give --beam\n");
    return 2;
  }
  demo::DemoSettings settings;
  if (!parse_size(o.size, settings.width, settings.height)) {
    std::fprintf(stderr, "glideshadows demo: --size '%s' must be WxH with each side 64..2048\n", o.size.c_str());
    return 2;
  }
  settings.frames = o.frames;
  settings.fps = o.fps;
  settings.shadow_size = o.shadow_size;
  settings.beam = o.beam;
  settings.out_dir = o.out_dir;
  const TechniqueOptions options = technique_options(o.choice, o.shadow_size);
  settings.shadow_options = options.projected;
  if (o.window) {
    demo::WindowSettings window;
    window.demo = settings;
    window.technique = o.choice.name;
    window.options = options;
    window.start_paused = o.paused;
    window.max_frames = o.frames_given ? o.frames : 0;
    return demo::play_fight_in_window(window, stdout);
  }
  std::string error;
  std::unique_ptr<ShadowTechnique> technique = make_technique(o.choice.name, options, error);
  if (!technique) {
    std::fprintf(stderr, "glideshadows demo: %s\n", error.c_str());
    return 2;
  }
  if (!open_window(settings.width, settings.height)) return 1;
  demo::DemoRun run;
  const bool ok = demo::render_fight(settings, *technique, run, error);
  grGlideShutdown();
  if (!ok) {
    std::fprintf(stderr, "glideshadows demo: %s\n", error.c_str());
    return 1;
  }
  for (const std::string &line : demo::warning_summary(run, o.frames)) {
    std::fprintf(stderr, "glideshadows demo: %s\n", line.c_str());
  }
  std::printf("glideshadows demo: %d frames %dx%d, technique %s, shadow texture %d, in %s/frame_NNNN.png\n",
              o.frames, settings.width, settings.height, o.choice.name.c_str(), o.shadow_size, o.out_dir.c_str());
  if (o.choice.name.rfind("projected", 0) == 0) {
    const char *how = o.choice.auto_size && o.choice.grow_size ? " (--auto-size and --grow-size, per fighter and frame)"
                      : o.choice.auto_size                       ? " (--auto-size, per fighter and frame)"
                      : o.choice.grow_size                       ? " (--grow-size, per fighter and frame)"
                                                                 : "";
    std::printf("shadow texture sides%s: %s\n", how, demo::describe_texture_sizes(run.texture_sizes).c_str());
  }
  const std::vector<std::string> table = demo::step_table(run.reports);
  if (!table.empty()) std::printf("\n");
  for (const std::string &line : table) std::printf("%s\n", line.c_str());
  if (o.sheet) {
    const std::string path = (std::filesystem::path(o.out_dir) / "contact_sheet.png").string();
    if (!media::write_contact_sheet(run.frame_files, path, error)) {
      std::fprintf(stderr, "glideshadows demo: cannot write %s: %s\n", path.c_str(), error.c_str());
      return 1;
    }
    std::printf("contact sheet: %s\n", path.c_str());
  }
  if (o.gif) {
    const std::string path = (std::filesystem::path(o.out_dir) / "fight.gif").string();
    if (!media::write_gif(run.frame_files, path, o.fps, error)) {
      std::fprintf(stderr, "glideshadows demo: cannot write %s: %s\n", path.c_str(), error.c_str());
      return 1;
    }
    std::printf("animated GIF: %s\n", path.c_str());
  }
  return 0;
}

}  // namespace

Command add_demo_command(CLI::App &app) {
  auto o = std::make_shared<DemoOptions>();
  CLI::App *demo = app.add_subcommand("demo", "render the fighting-game demo to PNG frames and print the step timing");
  // An option given twice takes its last value, so arguments after run.sh's defaults override them.
  demo->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  demo->add_option("--frames", o->frames, "number of frames (the default is one 8-second fight loop)")->check(CLI::Range(1, 100000))->capture_default_str();
  demo->add_option("--size", o->size, "screen size WxH")->capture_default_str();
  demo->add_option("--out", o->out_dir, "directory for frame_NNNN.png (an earlier run's frames there are removed)")
      ->capture_default_str();
  demo->add_option("--fps", o->fps, "animation frames per second of fight time")->check(CLI::Range(1, 240))->capture_default_str();
  demo->add_flag("--gif", o->gif, "also write an animated GIF (half size) of the frames");
  demo->add_flag("--contact-sheet", o->sheet, "also write a 4x4 contact sheet of frames from the run");
  // The demo is for watching: a fighter's shadow refused as too coarse at 256 texels is drawn
  // at the size the refusal names (--grow-size; 3 textures of the 192 in the 96 frames) rather
  // than missing. --no-grow-size shows the refusals.
  o->choice.grow_size = true;
  add_technique_options(*demo, o->choice, o->shadow_size);
  demo->add_option("--beam", o->beam.beam, "give the spotlight a projected beam map: round, square, gobo or lens")
      ->check(CLI::IsMember({"round", "square", "gobo", "lens"}));
  demo->add_option("--attenuation", o->beam.attenuation,
                   "the spotlight's attenuation with distance: none, vertex or exact (needs --beam)")
      ->check(CLI::IsMember({"none", "vertex", "exact"}))
      ->capture_default_str();
  demo->add_flag("--window", o->window,
                 "play the fight in a window (SDL2) instead of writing frames; --frames then stops "
                 "after that many frames. Keys below");
  demo->add_flag("--paused", o->paused, "with --window: start paused on the first frame")
      ->needs(demo->get_option("--window"));
  std::string keys = "Keys in the --window:\n";
  for (const std::string &line : demo::window_key_help()) keys += "  " + line + "\n";
  demo->footer(keys);
  CLI::Option *frames = demo->get_option("--frames");
  return {demo, [o, frames] {
            o->frames_given = frames->count() > 0;
            return run_demo(*o);
          }};
}

}  // namespace gs::cli
