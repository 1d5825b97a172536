// The benchmark's measurements. Time: the frame with the technique, ended by grSstIdle, median of
// `repeats` after one warm-up (llvmpipe compiles new state on first use). Error: the technique's
// mask against the ground truth's, over the visible pixels that are not only self-shadowed.
#include "speed_error.h"

#include "ground_truth.h"

#include <glide.h>
#include <glide_shim.h>

#include <algorithm>
#include <chrono>

namespace gs {
namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

BenchConfiguration configuration(const std::string &technique, const std::string &settings,
                                 const std::function<void(TechniqueOptions &)> &set) {
  BenchConfiguration c{technique, {}, settings};
  set(c.options);
  return c;
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
          "depth-map", "size " + std::to_string(size) + (linear ? " pcf" : " nearest") + " bias 1/4",
          [=](TechniqueOptions &o) {
            o.projected.size = size;
            o.depth_map_linear = linear;
          }));
    }
  }
  if (!quick) {
    list.push_back(configuration("depth-map", "size 256 pcf bias 2/8", [](TechniqueOptions &o) {
      o.projected.size = 256;
      o.depth_bias_slope = 2.0f;
      o.depth_bias_units = 8.0f;
    }));
  }
  using Mode = TechniqueOptions::VolumeMode;
  list.push_back(configuration("stencil-volume", "auto", [](TechniqueOptions &) {}));
  if (!quick) {
    list.push_back(configuration("stencil-volume", "zpass",
                                 [](TechniqueOptions &o) { o.volume_mode = Mode::ZPass; }));
    list.push_back(configuration("stencil-volume", "zfail",
                                 [](TechniqueOptions &o) { o.volume_mode = Mode::ZFail; }));
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
  for (const BenchFrame &frame : frames) {
    const Scene &scene = frame.scene;
    GroundTruth truth;
    if (!compute_ground_truth(scene, truth, error)) return false;
    std::vector<std::uint8_t> receivers(truth.object.size());
    long visible = 0, self_only = 0;
    for (std::size_t i = 0; i < receivers.size(); ++i) {
      const bool seen = truth.object[i] >= 0;
      visible += seen;
      self_only += seen && truth.self_shadow[i] && !truth.shadow[i];
      receivers[i] = seen && !(truth.self_shadow[i] && !truth.shadow[i]);
    }
    grGlideInit();
    if (!glideShimSetWindowSize(scene.width, scene.height) ||
        !grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                      GR_ORIGIN_UPPER_LEFT, 2, 1)) {
      error = std::string("cannot open the Glide window: ") + glideShimGetLastErrorMessage();
      return false;
    }
    double none_ms = 0.0;
    for (const BenchConfiguration &config : configurations) {
      progress(++done, total, frame.name + ": " + config.technique + " " + config.settings);
      std::unique_ptr<ShadowTechnique> technique = make_technique(config.technique, config.options, error);
      if (!technique) return false;
      technique->render(scene, false);  // warm-up: llvmpipe compiles this state's shaders
      std::vector<double> times;
      for (int r = 0; r < repeats; ++r) {
        const auto start = Clock::now();
        technique->render(scene, false);
        grSstIdle();
        times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
      }
      BenchRow row;
      row.frame = frame.name;
      row.technique = config.technique;
      row.settings = config.settings;
      row.frame_ms = median(times);
      if (config.technique == "none") none_ms = row.frame_ms;
      row.ratio_to_none = none_ms > 0.0 ? row.frame_ms / none_ms : 0.0;
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
      technique->render_mask(scene);
      row.errors = compare_masks(read_mask_from_back_buffer(scene.width, scene.height),
                                 truth.shadow, receivers, scene.width, scene.height);
      row.self_shadow = visible > 0 ? static_cast<double>(self_only) / static_cast<double>(visible) : 0.0;
      rows.push_back(row);
    }
    grGlideShutdown();
  }
  return true;
}

}  // namespace gs
