// The demo driver (fight_demo.h): the fight at each frame's time, through the technique, to PNG.
#include "fight_demo.h"

#include "figures/figures_kit.h"
#include "measure/speed_error.h"
#include "media/media.h"
#include "scene/fight_scene.h"

#include <glide.h>
#include <glide_shim.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <unistd.h>

namespace gs::demo {
namespace {

void apply_beam(const DemoBeam &choice, SpotLight &light) {
  light.beam = choice.beam;
  // Falls to about half at the far rope (8 m from the light along its axis).
  light.attenuation = {AttenuationMode::None, 1.0f, 0.0f, 0.015f};
  if (choice.attenuation == "vertex") light.attenuation.mode = AttenuationMode::PerVertex;
  if (choice.attenuation == "exact") light.attenuation.mode = AttenuationMode::PerPixel;
}

void report_progress(int done, int total, bool tty) {
  if (tty) {
    std::fprintf(stderr, "\rframe %d/%d", done, total);
    if (done == total) std::fprintf(stderr, "\n");
  } else if (done % std::max(1, total / 10) == 0 || done == total) {
    std::fprintf(stderr, "frame %d/%d\n", done, total);
  }
}

}  // namespace

Scene demo_scene_at(FightScene &fight, const DemoSettings &settings, float time) {
  Scene scene = fight.at(time);
  if (!settings.beam.beam.empty() || settings.beam.attenuation != "none") {
    apply_beam(settings.beam, scene.lights.front());
  }
  return scene;
}

Scene demo_frame_scene(FightScene &fight, const DemoSettings &settings, int index) {
  return demo_scene_at(fight, settings, static_cast<float>(index) / static_cast<float>(settings.fps));
}

std::vector<int> fighter_texture_sizes(const Scene &scene, const ProjectedShadowOptions &options,
                                       const std::vector<DrawnShadowSize> &drawn) {
  std::vector<int> sizes;
  for (std::size_t fighter : FightScene::kFighters) {
    const LightView view = fit_light_view(scene, fighter, 0, options);
    const int drawn_size = drawn_shadow_size(drawn, 0, fighter);
    sizes.push_back(!view.usable ? 0 : drawn_size > 0 ? drawn_size : view.size);
  }
  return sizes;
}

void count_warnings(const FrameReport &frame, int index, DemoRun &run) {
  std::vector<std::string> seen;  // this frame's, each counted once
  for (const std::string &w : frame.warnings) {
    if (std::find(seen.begin(), seen.end(), w) != seen.end()) continue;
    seen.push_back(w);
    auto counted = std::find_if(run.warnings.begin(), run.warnings.end(),
                                [&w](const WarningCount &c) { return c.text == w; });
    if (counted == run.warnings.end()) {
      const bool error = std::find(frame.errors.begin(), frame.errors.end(), w) != frame.errors.end();
      counted = run.warnings.insert(run.warnings.end(), WarningCount{w, 0, error});
    }
    ++counted->frames;
  }
  if (!frame.errors.empty()) run.frames_missing_shadow.push_back(index);
}

std::vector<std::string> warning_summary(const DemoRun &run, int frames) {
  constexpr std::size_t kFramesNamed = 12;  // frame numbers listed, the first ones
  std::string missing = std::to_string(run.frames_missing_shadow.size()) + " of " +
                        std::to_string(frames) + " frames lack a shadow they should show";
  for (std::size_t i = 0; i < run.frames_missing_shadow.size() && i < kFramesNamed; ++i) {
    missing += (i == 0 ? " (frames " : ", ") + std::to_string(run.frames_missing_shadow[i]);
  }
  if (run.frames_missing_shadow.size() > kFramesNamed) missing += ", ...";
  if (!run.frames_missing_shadow.empty()) missing += "; the errors below say why)";
  std::vector<std::string> lines = {missing};
  for (const WarningCount &w : run.warnings) {
    lines.push_back(std::string(w.error ? "error" : "warning") + " in " + std::to_string(w.frames) +
                    " of " + std::to_string(frames) + " frames: " + w.text);
  }
  return lines;
}

InterFighterShadow measure_inter_fighter_shadow(ShadowTechnique &technique, const Scene &scene) {
  technique.render(scene, false);
  technique.render_mask(scene);
  const figures::Mask mask = figures::non_zero(figures::read_back(scene.width, scene.height));
  InterFighterShadow result;
  for (int i = 0; i < 2; ++i) {
    result.pixels[i] = figures::count_both(mask, figures::coverage(scene, FightScene::kFighters[i]));
  }
  result.share = static_cast<double>(result.pixels[0] + result.pixels[1]) /
                 (static_cast<double>(scene.width) * static_cast<double>(scene.height));
  return result;
}

std::string describe_texture_sizes(const std::vector<int> &sizes) {
  std::map<int, int> frames_of_size;
  for (int size : sizes) ++frames_of_size[size];
  std::string text;
  for (const auto &[size, count] : frames_of_size) {
    if (!text.empty()) text += ", ";
    text += std::to_string(size) + " in " + std::to_string(count) + " textures";
  }
  return text;
}

bool render_fight(const DemoSettings &settings, ShadowTechnique &technique, DemoRun &run,
                  std::string &error) {
  if (!media::prepare_frame_directory(settings.out_dir, error)) return false;
  FightScene fight(settings.width, settings.height, settings.shadow_size);
  const bool tty = isatty(fileno(stderr)) != 0;
  for (int i = 0; i < settings.frames; ++i) {
    const Scene scene = demo_frame_scene(fight, settings, i);
    const FrameReport frame = technique.render(scene, true);
    if (i > 0) run.reports.push_back(frame);
    count_warnings(frame, i, run);
    for (int size : fighter_texture_sizes(scene, settings.shadow_options, frame.shadow_sizes)) {
      run.texture_sizes.push_back(size);
    }
    grBufferSwap(1);
    const std::string path = media::frame_path(settings.out_dir, i);
    if (!glideShimWritePng(GR_BUFFER_FRONTBUFFER, path.c_str())) {
      if (tty) std::fprintf(stderr, "\n");
      error = glideShimGetLastErrorMessage();
      return false;
    }
    run.frame_files.push_back(path);
    report_progress(i + 1, settings.frames, tty);
  }
  return true;
}

std::vector<std::string> step_table(const std::vector<FrameReport> &reports) {
  std::vector<std::string> lines;
  if (reports.empty()) return lines;
  std::vector<double> total;
  for (const FrameReport &r : reports) total.push_back(r.total_ms);
  const double frame = median(total);
  char line[160];
  std::snprintf(line, sizeof line, "Step timing (median of %zu frames, each step synchronised):", reports.size());
  lines.emplace_back(line);
  for (std::size_t step = 0; step < reports.front().steps.size(); ++step) {
    std::vector<double> values;
    for (const FrameReport &r : reports) values.push_back(r.steps[step].second);
    const double ms = median(values);
    std::snprintf(line, sizeof line, "  step %-44s %7.2f ms  %5.1f%%", reports.front().steps[step].first.c_str(),
                  ms, frame > 0 ? 100.0 * ms / frame : 0.0);
    lines.emplace_back(line);
  }
  std::snprintf(line, sizeof line, "  %-49s %7.2f ms  (%.0f frames/s)", "whole frame", frame,
                frame > 0 ? 1000.0 / frame : 0.0);
  lines.emplace_back(line);
  return lines;
}

}  // namespace gs::demo
