// `glideshadows bench`: speed against error of every technique and setting, on fight frames and
// scene files, as a table, and optionally a CSV, a plot with the Pareto front and the cheapest
// configuration within an error budget.
#include "cli/commands.h"
#include "cli/options.h"
#include "measure/plot.h"
#include "measure/speed_error.h"
#include "scene/fight_scene.h"
#include "scene/scene.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace gs::cli {
namespace {

struct BenchOptions {
  std::vector<std::string> scenes;
  bool quick = false;
  int repeats = 5;
  std::string csv, plot;
  double budget = -1.0;  // negative: no budget question
};

int run_bench_command(std::vector<std::string> scene_files, bool quick, int repeats, const std::string &csv,
                      const std::string &plot, double budget) {
  std::vector<BenchFrame> frames;
  FightScene fight(640, 480, 256);
  for (float time : quick ? std::vector<float>{2.1f} : std::vector<float>{0.5f, 2.1f, 5.3f}) {
    char name[32];
    std::snprintf(name, sizeof name, "%s%.1f", kFightFramePrefix, static_cast<double>(time));
    frames.push_back({name, fight.at(time)});
  }
  if (scene_files.empty() && !quick && fs::is_directory("scenes")) {
    for (const auto &entry : fs::directory_iterator("scenes")) {
      if (entry.path().extension() == ".json") scene_files.push_back(entry.path().string());
    }
    std::sort(scene_files.begin(), scene_files.end());
  }
  for (const std::string &file : scene_files) {
    Scene scene;
    std::string error;
    if (!load_scene(file, scene, error)) {
      std::fprintf(stderr, "glideshadows bench: %s\n", error.c_str());
      return 1;
    }
    frames.push_back({fs::path(file).stem().string(), std::move(scene)});
  }
  const std::vector<BenchConfiguration> configurations = bench_configurations(quick);
  const bool tty = isatty(fileno(stderr)) != 0;
  std::vector<BenchRow> rows;
  std::string error;
  const bool ok = run_bench(frames, configurations, repeats,
      [&](int done, int total, const std::string &what) {
        if (tty) std::fprintf(stderr, "\r[%d/%d] %-60.60s", done, total, what.c_str());
        else if (done % 10 == 1 || done == total) std::fprintf(stderr, "[%d/%d] %s\n", done, total, what.c_str());
      },
      rows, error);
  if (tty) std::fprintf(stderr, "\n");
  if (!ok) {
    std::fprintf(stderr, "glideshadows bench: %s\n", error.c_str());
    return 1;
  }
  std::printf("%-16s %-16s %-38s %8s %6s %8s %8s %8s %6s %7s %6s\n", "frame", "technique",
              "settings", "ms", "x none", "wrong%", "band%", "inner%", "maxpx", "img err", "PSNR");
  for (const BenchRow &r : rows) {
    if (r.failed) {
      std::printf("%-16s %-16s %-38s %8.2f %6.2f FAILED: %s\n", r.frame.c_str(), r.technique.c_str(),
                  r.settings.c_str(), r.frame_ms, r.ratio_to_none, r.failure.c_str());
      continue;
    }
    const double band = r.errors.false_shadow_band + r.errors.false_light_band;
    const double inner = r.errors.false_shadow_interior + r.errors.false_light_interior;
    std::printf("%-16s %-16s %-38s %8.2f %6.2f %8.3f %8.3f %8.3f %6.1f %7.2f %6.1f\n",
                r.frame.c_str(), r.technique.c_str(), r.settings.c_str(), r.frame_ms,
                r.ratio_to_none, 100 * r.errors.misclassified, 100 * band, 100 * inner,
                r.errors.max_distance_px, 255 * r.image.mean, r.image.psnr);
  }
  std::printf("(wrong%%: receiver pixels misclassified; img err: mean absolute error of the whole "
              "frame against the truth's exactly lit image, in 8-bit steps; FAILED: the technique "
              "could not cast a shadow the frame has, so the row is not scored)\n\n");
  for (const std::string &line : article_step_comparison(rows)) std::printf("%s\n", line.c_str());
  if (!csv.empty()) {
    std::FILE *out = std::fopen(csv.c_str(), "w");
    if (out == nullptr) {
      std::fprintf(stderr, "glideshadows bench: cannot write %s\n", csv.c_str());
      return 1;
    }
    std::fprintf(out, "frame,technique,settings,frame_ms,ratio_to_none,misclassified,false_shadow_band,"
                      "false_shadow_interior,false_light_band,false_light_interior,max_distance_px,"
                      "self_shadow,image_mean_error,image_psnr,steps,failed\n");
    for (const BenchRow &r : rows) {
      std::string steps;
      for (const auto &s : r.steps) steps += (steps.empty() ? "" : ";") + s.first + "=" + std::to_string(s.second);
      if (r.failed) {  // no measurement: the error columns are empty
        std::fprintf(out, "%s,%s,%s,%.4f,%.4f,,,,,,,,,,\"%s\",\"%s\"\n", r.frame.c_str(),
                     r.technique.c_str(), r.settings.c_str(), r.frame_ms, r.ratio_to_none,
                     steps.c_str(), r.failure.c_str());
        continue;
      }
      std::fprintf(out, "%s,%s,%s,%.4f,%.4f,%.6f,%.6f,%.6f,%.6f,%.6f,%.2f,%.6f,%.6f,%.2f,\"%s\",\n",
                   r.frame.c_str(), r.technique.c_str(), r.settings.c_str(), r.frame_ms, r.ratio_to_none,
                   r.errors.misclassified, r.errors.false_shadow_band, r.errors.false_shadow_interior,
                   r.errors.false_light_band, r.errors.false_light_interior, r.errors.max_distance_px,
                   r.self_shadow, r.image.mean, r.image.psnr, steps.c_str());
    }
    std::fclose(out);
    std::printf("CSV: %s\n", csv.c_str());
  }
  if (!plot.empty()) {
    // One point per configuration measured on every frame: its mean time and mean error. (The
    // attenuation settings apply to the spotlight scenes only, so they are left out.)
    std::vector<PlotPoint> points;
    for (std::size_t c = 0; c < configurations.size(); ++c) {
      double time = 0, wrong = 0;
      std::size_t n = 0;
      for (const BenchRow &r : rows) {
        if (r.configuration != c || r.failed) continue;  // a failed row is never scored
        time += r.frame_ms, wrong += r.errors.misclassified, ++n;
      }
      if (n == frames.size() && n > 0)
        points.push_back({time / static_cast<double>(n), wrong / static_cast<double>(n),
                          configurations[c].technique});
    }
    if (!write_plot(points, "error against frame time (mean over frames)", plot, error)) {
      std::fprintf(stderr, "glideshadows bench: %s\n", error.c_str());
      return 1;
    }
    std::printf("plot: %s\n", plot.c_str());
  }
  if (budget >= 0.0) {
    for (const BenchFrame &frame : frames) {
      const BenchRow *best = nullptr;
      for (const BenchRow &r : rows) {
        if (r.failed || r.frame != frame.name || r.technique == "none" ||
            r.errors.misclassified > budget)
          continue;
        if (best == nullptr || r.frame_ms < best->frame_ms) best = &r;
      }
      if (best == nullptr) {
        std::printf("budget %.4f, %s: no configuration is that accurate\n", budget, frame.name.c_str());
      } else {
        std::printf("budget %.4f, %s: %s %s (%.2f ms, %.3f%% wrong)\n", budget, frame.name.c_str(),
                    best->technique.c_str(), best->settings.c_str(), best->frame_ms,
                    100 * best->errors.misclassified);
      }
    }
  }
  return 0;
}

}  // namespace

Command add_bench_command(CLI::App &app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App *bench = app.add_subcommand("bench", "speed against error of every technique and setting");
  bench->add_option("scenes", o->scenes, "scene files (default: fight frames and scenes/*.json)");
  bench->add_flag("--quick", o->quick, "a few configurations on one fight frame (under a minute)");
  bench->add_option("--repeats", o->repeats, "timed repeats per configuration (median)")
      ->check(CLI::Range(1, 100))->capture_default_str();
  bench->add_option("--csv", o->csv, "write one row per frame and configuration");
  bench->add_option("--plot", o->plot, "write error against time as a PNG with the Pareto front");
  bench->add_option("--budget", o->budget, "name the cheapest configuration with at most this error (fraction)")
      ->check(finite_number())
      ->check(CLI::Range(0.0, 1.0));
  return {bench, [o] { return run_bench_command(o->scenes, o->quick, o->repeats, o->csv, o->plot, o->budget); }};
}

}  // namespace gs::cli
