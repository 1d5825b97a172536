// The deliberate mistakes each figure's checks must catch: for every check of every figure
// (besides Glide's error check, caught by FigureFault::InvalidGlideCall), a fault and the words
// of the check's claim that must then fail. figure_faults_test.cpp renders each; figures_test.cpp
// holds every figure's checks against this list, so a new check without a fault fails there.
#pragma once

#include "figures/figures.h"

#include <string>
#include <vector>

struct FigureFaultCase {
  const char *figure;     // a figure_table() name
  gs::FigureFault fault;
  const char *claim;      // words of the claim of the check the fault must fail
};

inline const std::vector<FigureFaultCase> &figure_fault_cases() {
  using F = gs::FigureFault;
  static const std::vector<FigureFaultCase> cases = {
      {"nguyen-16", F::InvalidGlideCall, "Glide reported no error"},
      {"nguyen-8", F::StaleReadBack, "in the right panel"},
  };
  return cases;
}

// True when some case names `figure` and a claim containing its words.
inline bool has_fault_case(const std::string &figure, const std::string &claim) {
  for (const FigureFaultCase &c : figure_fault_cases()) {
    if (figure == c.figure && claim.find(c.claim) != std::string::npos) return true;
  }
  return false;
}
