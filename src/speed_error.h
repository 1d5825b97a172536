// Speed against error: every technique and its settings over a set of frames, each timed (median
// of repeats after a warm-up, and as a ratio to the frame without shadows in the same run) and
// measured against the ray-cast ground truth. The engine of `glideshadows bench`.
#pragma once

#include "metrics.h"
#include "scene.h"
#include "technique.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace gs {

struct BenchConfiguration {
  std::string technique;  // a make_technique name
  TechniqueOptions options;
  std::string settings;   // what distinguishes it, for tables ("size 256 bilinear lfb")
};

struct BenchFrame {
  std::string name;  // "fight t=2.1", a scene file's name
  Scene scene;
};

struct BenchRow {
  std::string frame, technique, settings;
  double frame_ms = 0.0;        // median over repeats
  double ratio_to_none = 0.0;   // against technique "none" on the same frame, same run
  std::vector<std::pair<std::string, double>> steps;  // median step times, synchronised
  MaskErrors errors;            // against the truth, self-shadowing excluded
  double self_shadow = 0.0;     // fraction of visible pixels only self-shadowed (not counted)
};

std::vector<BenchConfiguration> bench_configurations(bool quick);

// Opens a Glide window per frame size, measures every configuration on every frame, and returns
// a row per (frame, configuration). `progress` is told (done, total, what) as it goes. False with
// `error` on a failure that stops the run (a window that cannot open, the truth failing).
bool run_bench(const std::vector<BenchFrame> &frames,
               const std::vector<BenchConfiguration> &configurations, int repeats,
               const std::function<void(int, int, const std::string &)> &progress,
               std::vector<BenchRow> &rows, std::string &error);

}  // namespace gs
