// Speed against error: every technique and its settings over a set of frames, each timed (median
// of repeats after a warm-up, and as a ratio to the frame without shadows in the same run) and
// measured against the ray-cast ground truth. The engine of `glideshadows bench`.
#pragma once

#include "measure/metrics.h"
#include "scene/scene.h"
#include "techniques/technique.h"

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gs {

struct BenchConfiguration {
  std::string technique;  // a make_technique name
  TechniqueOptions options;
  std::string settings;   // what distinguishes it, for tables ("size 256 bilinear lfb")
  // Set: the attenuation mode given to every attenuated spotlight with a beam map, and only
  // frames that have one are measured. Unset: the frame as its scene says.
  std::optional<AttenuationMode> attenuation;
};

// The name of each fight frame the bench measures starts with this ("fight t=2.1"); a scene
// file's frame is named for its file ("fighters"), which may start with "fight" too.
inline constexpr const char *kFightFramePrefix = "fight t=";

struct BenchFrame {
  std::string name;  // "fight t=2.1", a scene file's name
  Scene scene;
};

struct BenchRow {
  std::size_t configuration = 0;  // index into the configurations measured
  std::string frame, technique, settings;
  double frame_ms = 0.0;        // median over repeats
  double ratio_to_none = 0.0;   // against technique "none" on the same frame, same run
  std::vector<std::pair<std::string, double>> steps;  // median step times, synchronised
  MaskErrors errors;            // against the truth, self-shadowing excluded
  ImageErrors image;            // the whole frame against the truth's exactly lit image
  double self_shadow = 0.0;     // fraction of visible pixels only self-shadowed (not counted)
  // The technique reported shadows it could not cast (FrameReport::errors, the first here): the
  // row is a failure, its errors are not measured and it is never scored or plotted.
  bool failed = false;
  std::string failure;
  double texel_footprint_px = 0.0;  // FrameReport::texel_footprint_px of the first render
};

std::vector<BenchConfiguration> bench_configurations(bool quick);

// The pixels the frame without shadows draws a surface on (1; 0 where it shows the background),
// rows from the top: the scene pass every technique's frame shares, rendered into the open
// Glide window's back buffer, whose contents it replaces. A receiver pixel of the ray-cast truth
// that this frame leaves as background is one no technique's frame shadows (compare_masks).
std::vector<std::uint8_t> drawn_without_shadows(const Scene &scene);

// The median of `values` (the upper one of an even count); 0 for none.
double median(std::vector<double> values);

// Opens a Glide window per frame size, measures every configuration on every frame it applies
// to, and returns a row per (frame, configuration) measured. `progress` is told (done, total, what) as it goes. False with
// `error` on a failure that stops the run (a window that cannot open, the truth failing).
bool run_bench(const std::vector<BenchFrame> &frames,
               const std::vector<BenchConfiguration> &configurations, int repeats,
               const std::function<void(int, int, const std::string &)> &progress,
               std::vector<BenchRow> &rows, std::string &error);

// The article's statements about its step times (Nguyen 1999: copying the frame is the slowest
// step; rendering straight into texture memory would make the sample about 50 percent faster;
// step 3 is 15 to 20 percent of the frame) beside what the rows measured, as printable lines.
std::vector<std::string> article_step_comparison(const std::vector<BenchRow> &rows);

}  // namespace gs
