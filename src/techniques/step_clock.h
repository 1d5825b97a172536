// The clock of the per-step times every technique reports (FrameReport::steps, the projected
// shadow's five step times): milliseconds of the steady clock since a step began.
#pragma once

#include <chrono>

namespace gs {

inline double elapsed_ms(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace gs
