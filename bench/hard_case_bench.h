// hard_case_sweeps' one way of measuring (hard_case_sweeps.cpp, hard_case_footprint.cpp): every
// configuration on every frame once, without progress, a failure printed with the sweep's name;
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
  if (gs::run_bench(frames, configurations, 1, [](int, int, const std::string &) {}, rows, error)) {
    return true;
  }
  std::fprintf(stderr, "hard_case_sweeps: %s: %s\n", sweep.c_str(), error.c_str());
  return false;
}

}  // namespace hard_cases
