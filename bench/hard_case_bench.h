// hard_case_sweeps' one way of measuring (hard_case_sweeps.cpp, hard_case_footprint.cpp): every
// configuration on every frame once, its progress and a failure on stderr with the sweep's name;
// and a technique's configuration at its defaults.
#pragma once

#include "measure/speed_error.h"

#include <cstdio>
#include <string>
#include <vector>

namespace hard_cases {

// A technique at its defaults.
inline gs::BenchConfiguration plain(const std::string &technique) {
  gs::BenchConfiguration c;
  c.technique = technique;
  return c;
}

// run_bench's rows (frame-major, configurations in order) in `rows`; false, said on stderr,
// when a configuration could not render.
inline bool measure_once(const std::vector<gs::BenchFrame> &frames,
                         const std::vector<gs::BenchConfiguration> &configurations,
                         const std::string &sweep, std::vector<gs::BenchRow> &rows) {
  std::string error;
  // A line as each frame starts (its first configuration), and the last: a sweep of many scene
  // files runs for minutes, and a scene that never finishes is named by the last line written.
  const int per_frame = static_cast<int>(configurations.size());
  const auto progress = [&sweep, per_frame](int done, int total, const std::string &what) {
    if (per_frame > 0 && ((done - 1) % per_frame == 0 || done == total)) {
      std::fprintf(stderr, "hard_case_sweeps %s: [%d/%d] %s\n", sweep.c_str(), done, total,
                   what.c_str());
    }
  };
  if (gs::run_bench(frames, configurations, 1, progress, rows, error)) return true;
  std::fprintf(stderr, "hard_case_sweeps: %s: %s\n", sweep.c_str(), error.c_str());
  return false;
}

}  // namespace hard_cases
