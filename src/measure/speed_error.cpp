// The benchmark's measurements. Time: the frame with the technique, ended by grSstIdle, median of
// `repeats` after one warm-up (llvmpipe compiles new state on first use). Error: the technique's
// mask against the ground truth's, over the visible pixels that are not only self-shadowed.
#include "measure/speed_error.h"

#include "measure/ground_truth.h"
#include "techniques/light_passes/scene_pass.h"

#include <glide.h>
#include <glide_shim.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>

namespace gs {
double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

namespace {

BenchConfiguration configuration(const std::string &technique, const std::string &settings,
                                 const std::function<void(TechniqueOptions &)> &set) {
  BenchConfiguration c{technique, {}, settings, std::nullopt};
  set(c.options);
  return c;
}

// " bias S/U": the depth map's glPolygonOffset slope factor and units as a row's label says them,
// from the options the row runs with (so a change of the defaults cannot leave a label behind).
std::string depth_bias_label(const TechniqueOptions &options) {
  char label[48];
  std::snprintf(label, sizeof label, " bias %g/%g", static_cast<double>(options.depth_bias_slope),
                static_cast<double>(options.depth_bias_units));
  return label;
}

// The back buffer as 8-bit RGB, each 565 field widened by bit replication.
std::vector<std::uint8_t> read_rgb_from_back_buffer(int width, int height) {
  std::vector<FxU16> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, static_cast<FxU32>(width), static_cast<FxU32>(height),
                  static_cast<FxU32>(width) * 2, pixels.data());
  std::vector<std::uint8_t> rgb(pixels.size() * 3);
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const unsigned r = pixels[i] >> 11, g = pixels[i] >> 5 & 0x3F, b = pixels[i] & 0x1F;
    rgb[i * 3 + 0] = static_cast<std::uint8_t>(r << 3 | r >> 2);
    rgb[i * 3 + 1] = static_cast<std::uint8_t>(g << 2 | g >> 4);
    rgb[i * 3 + 2] = static_cast<std::uint8_t>(b << 3 | b >> 2);
  }
  return rgb;
}

// The frame as `configuration` measures it: its attenuation mode given to the attenuated
// spotlights with beam maps. False when the configuration does not apply to the frame.
bool adjusted_scene(const Scene &scene, const BenchConfiguration &configuration, Scene &adjusted) {
  adjusted = scene;
  if (!configuration.attenuation) return true;
  bool applies = false;
  for (SpotLight &light : adjusted.lights) {
    if (!light.has_beam_map() || light.attenuation.mode == AttenuationMode::None) continue;
    light.attenuation.mode = *configuration.attenuation;
    applies = true;
  }
  return applies;
}

std::vector<std::uint8_t> read_mask_from_back_buffer(int width, int height) {
  std::vector<FxU16> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, static_cast<FxU32>(width), static_cast<FxU32>(height),
                  static_cast<FxU32>(width) * 2, pixels.data());
  std::vector<std::uint8_t> mask(pixels.size());
  for (std::size_t i = 0; i < pixels.size(); ++i) mask[i] = pixels[i] != 0;
  return mask;
}

}  // namespace

std::vector<std::uint8_t> drawn_without_shadows(const Scene &scene) {
  render_scene(scene, project_scene(scene));
  // W codes: the scene pass clears to the farthest, and any surface a scene can hold lies nearer
  // (its far plane is well inside the W range).
  const int width = scene.width, height = scene.height;
  std::vector<FxU16> codes(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  grLfbReadRegion(GR_BUFFER_AUXBUFFER, 0, 0, static_cast<FxU32>(width), static_cast<FxU32>(height),
                  static_cast<FxU32>(width) * 2, codes.data());
  std::vector<std::uint8_t> drawn(codes.size());
  for (std::size_t i = 0; i < codes.size(); ++i) drawn[i] = codes[i] != GR_WDEPTHVALUE_FARTHEST;
  return drawn;
}

std::vector<BenchConfiguration> bench_configurations(bool quick) {
  std::vector<BenchConfiguration> list;
  list.push_back(configuration("none", "", [](TechniqueOptions &) {}));
  const std::vector<int> sizes = quick ? std::vector<int>{64, 256} : std::vector<int>{32, 64, 128, 256, 512};
  for (int size : sizes) {
    for (bool bilinear : quick ? std::vector<bool>{true} : std::vector<bool>{true, false}) {
      for (bool direct : quick ? std::vector<bool>{false} : std::vector<bool>{false, true}) {
        list.push_back(configuration(
            "projected",
            "size " + std::to_string(size) + (bilinear ? " bilinear" : " point") + (direct ? " direct" : " lfb"),
            [=](TechniqueOptions &o) {
              o.projected.size = size;
              o.projected.bilinear = bilinear;
              o.projected.direct_path = direct;
            }));
      }
    }
  }
  if (!quick) {
    for (int size : {64, 256}) {
      list.push_back(configuration("projected-chroma", "size " + std::to_string(size),
                                   [=](TechniqueOptions &o) { o.projected.size = size; }));
    }
  }
  list.push_back(configuration("planar", "", [](TechniqueOptions &) {}));
  for (int size : quick ? std::vector<int>{256} : std::vector<int>{256, 1024}) {
    for (bool linear : quick ? std::vector<bool>{true} : std::vector<bool>{true, false}) {
      list.push_back(configuration(
          "depth-map", "size " + std::to_string(size) + (linear ? " pcf" : " nearest") +
                           depth_bias_label(TechniqueOptions{}),
          [=](TechniqueOptions &o) {
            o.projected.size = size;
            o.depth_map_linear = linear;
          }));
    }
  }
  if (!quick) {
    // Twice the default slope factor (the default early in issue 14): less acne, more
    // peter-panning.
    TechniqueOptions steeper;
    steeper.depth_bias_slope = 2.0f * steeper.depth_bias_slope;
    list.push_back(configuration("depth-map", "size 256 pcf" + depth_bias_label(steeper),
                                 [=](TechniqueOptions &o) {
                                   o.projected.size = 256;
                                   o.depth_bias_slope = steeper.depth_bias_slope;
                                 }));
  }
  using Mode = TechniqueOptions::VolumeMode;
  list.push_back(configuration("stencil-volume", "auto", [](TechniqueOptions &) {}));
  if (!quick) {
    list.push_back(configuration("stencil-volume", "zpass",
                                 [](TechniqueOptions &o) { o.volume_mode = Mode::ZPass; }));
    list.push_back(configuration("stencil-volume", "zfail",
                                 [](TechniqueOptions &o) { o.volume_mode = Mode::ZFail; }));
    // Spotlight attenuation per vertex against exact per pixel, on the frames with one.
    for (AttenuationMode mode : {AttenuationMode::PerVertex, AttenuationMode::PerPixel}) {
      const std::string name =
          mode == AttenuationMode::PerVertex ? "attenuation vertex" : "attenuation exact";
      list.push_back(configuration("none", name, [](TechniqueOptions &) {}));
      list.push_back(configuration("projected", "size 256 bilinear lfb " + name,
                                   [](TechniqueOptions &o) { o.projected.size = 256; }));
      list.push_back(configuration("depth-map", "size 256 pcf" + depth_bias_label(TechniqueOptions{}) + " " + name,
                                   [](TechniqueOptions &o) { o.projected.size = 256; }));
      for (std::size_t i = list.size() - 3; i < list.size(); ++i) list[i].attenuation = mode;
    }
  }
  return list;
}

bool run_bench(const std::vector<BenchFrame> &frames,
               const std::vector<BenchConfiguration> &configurations, int repeats,
               const std::function<void(int, int, const std::string &)> &progress,
               std::vector<BenchRow> &rows, std::string &error) {
  using Clock = std::chrono::steady_clock;
  const int total = static_cast<int>(frames.size() * configurations.size());
  int done = 0;
  Scene scene;
  for (const BenchFrame &frame : frames) {
    // The truth is the same for every attenuation mode: it evaluates the function exactly.
    GroundTruth truth;
    if (!compute_ground_truth(frame.scene, truth, error)) return false;
    std::vector<std::uint8_t> receivers(truth.object.size()), self_only_shadow(truth.object.size());
    long visible = 0, self_only = 0;
    for (std::size_t i = 0; i < receivers.size(); ++i) {
      const bool seen = truth.object[i] >= 0;
      visible += seen;
      self_only += seen && truth.self_shadow[i] && !truth.shadow[i];
      receivers[i] = seen && !(truth.self_shadow[i] && !truth.shadow[i]);
      self_only_shadow[i] = seen && !receivers[i];
    }
    const int width = frame.scene.width, height = frame.scene.height;
    grGlideInit();
    if (!glideShimSetWindowSize(width, height) ||
        !grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                      GR_ORIGIN_UPPER_LEFT, 2, 1)) {
      error = std::string("cannot open the Glide window: ") + glideShimGetLastErrorMessage();
      return false;
    }
    const std::vector<std::uint8_t> drawn = drawn_without_shadows(frame.scene);
    // The frame without shadows, per attenuation setting: each ratio compares like with like.
    std::map<std::optional<AttenuationMode>, double> none_ms;
    for (std::size_t c = 0; c < configurations.size(); ++c) {
      const BenchConfiguration &config = configurations[c];
      progress(++done, total, frame.name + ": " + config.technique + " " + config.settings);
      if (!adjusted_scene(frame.scene, config, scene)) continue;
      std::unique_ptr<ShadowTechnique> technique = make_technique(config.technique, config.options, error);
      if (!technique) return false;
      // Warm-up (llvmpipe compiles this state's shaders), and whether the technique can do the
      // frame at all: a frame missing shadows is a failed row, not a measurement.
      const FrameReport first = technique->render(scene, false);
      std::vector<double> times;
      for (int r = 0; r < repeats; ++r) {
        const auto start = Clock::now();
        technique->render(scene, false);
        grSstIdle();
        times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
      }
      BenchRow row;
      row.configuration = c;
      row.frame = frame.name;
      row.technique = config.technique;
      row.settings = config.settings;
      row.frame_ms = median(times);
      if (config.technique == "none") none_ms[config.attenuation] = row.frame_ms;
      const double baseline = none_ms[config.attenuation];
      row.ratio_to_none = baseline > 0.0 ? row.frame_ms / baseline : 0.0;
      std::vector<std::vector<double>> step_times;
      for (int r = 0; r < std::max(1, repeats / 2); ++r) {
        const FrameReport report = technique->render(scene, true);
        step_times.resize(report.steps.size());
        for (std::size_t s = 0; s < report.steps.size(); ++s) step_times[s].push_back(report.steps[s].second);
        if (row.steps.empty()) {
          for (const auto &step : report.steps) row.steps.emplace_back(step.first, 0.0);
        }
      }
      for (std::size_t s = 0; s < row.steps.size(); ++s) row.steps[s].second = median(step_times[s]);
      row.texel_footprint_px = first.texel_footprint_px;
      row.failed = !first.errors.empty();
      if (row.failed) {
        row.failure = first.errors.front();
        rows.push_back(row);
        continue;
      }
      std::string compare_error;
      if (!compare_rgb(read_rgb_from_back_buffer(width, height), truth.rgb, width, height,
                       row.image, compare_error)) {
        row.failed = true;
        row.failure = compare_error;
        rows.push_back(row);
        continue;
      }
      technique->render_mask(scene);
      row.errors = compare_masks(read_mask_from_back_buffer(width, height), truth.shadow,
                                 receivers, width, height, self_only_shadow, drawn);
      row.self_shadow = visible > 0 ? static_cast<double>(self_only) / static_cast<double>(visible) : 0.0;
      rows.push_back(row);
    }
    grGlideShutdown();
  }
  return true;
}

std::vector<std::string> article_step_comparison(const std::vector<BenchRow> &rows) {
  // The article's sample is the projected shadow texture at 256 texels with bilinear filtering;
  // its figures are for a whole frame, so ours are the means over the fight frames.
  auto mean_over_fight = [&](const std::string &settings, auto &&value) {
    double sum = 0.0;
    int n = 0;
    for (const BenchRow &r : rows) {
      if (r.failed || r.technique != "projected" || r.settings != settings ||
          r.frame.rfind(kFightFramePrefix, 0) != 0)
        continue;
      sum += value(r);
      ++n;
    }
    return n > 0 ? std::optional<double>(sum / n) : std::nullopt;
  };
  auto step_share = [](const BenchRow &r, std::size_t step) {
    double total = 0.0;
    for (const auto &s : r.steps) total += s.second;
    return step < r.steps.size() && total > 0.0 ? r.steps[step].second / total : 0.0;
  };
  std::vector<std::string> lines;
  char line[200];
  auto add = [&](const char *claim, const char *article, const std::string &ours) {
    std::snprintf(line, sizeof line, "  %-50s %-22s %s", claim, article, ours.c_str());
    lines.emplace_back(line);
  };
  auto percent = [](std::optional<double> v) {
    if (!v) return std::string("not measured");
    char text[32];
    std::snprintf(text, sizeof text, "%.0f%%", 100.0 * *v);
    return std::string(text);
  };
  const std::string lfb = "size 256 bilinear lfb", direct = "size 256 bilinear direct";
  lines.emplace_back("The article's step times beside ours (projected, size 256 bilinear, mean over the "
                     "fight frames; step times synchronised):");
  add("claim", "article", "ours");
  // The slowest step: the one with the largest mean share.
  std::optional<double> largest;
  std::size_t slowest = 0;
  std::string slowest_name = "not measured";
  for (std::size_t step = 0; step < 5; ++step) {
    const std::optional<double> share = mean_over_fight(lfb, [&](const BenchRow &r) { return step_share(r, step); });
    if (share && (!largest || *share > *largest)) {
      largest = share;
      slowest = step;
    }
  }
  for (const BenchRow &r : rows)
    if (largest && r.technique == "projected" && r.settings == lfb && slowest < r.steps.size())
      slowest_name = r.steps[slowest].first + " (" + percent(largest) + ")";
  add("slowest step", "2, copying the frame", slowest_name);
  add("step 2 (LFB read + download) share of the frame", "the largest",
      percent(mean_over_fight(lfb, [&](const BenchRow &r) { return step_share(r, 1); })));
  add("step 3 ((s,t) for the receivers) share", "15 to 20%",
      percent(mean_over_fight(lfb, [&](const BenchRow &r) { return step_share(r, 2); })));
  const std::optional<double> lfb_ms = mean_over_fight(lfb, [](const BenchRow &r) { return r.frame_ms; });
  const std::optional<double> direct_ms =
      mean_over_fight(direct, [](const BenchRow &r) { return r.frame_ms; });
  add("rendering straight into texture memory", "about 50% faster",
      !lfb_ms || !direct_ms ? std::string("not measured (the direct path is not in --quick)")
      : *lfb_ms >= *direct_ms ? percent(*lfb_ms / *direct_ms - 1.0) + " faster"
                              : percent(1.0 - *lfb_ms / *direct_ms) + " slower");
  return lines;
}

}  // namespace gs
