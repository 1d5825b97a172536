// The deliberate mistakes each figure's checks must catch: for every check of every figure
// (besides Glide's error check, caught by FigureFault::InvalidGlideCall), a fault and the words
// of the check's claim that must then fail. figure_faults_test.cpp renders each; figures_test.cpp
// holds every figure's checks against this list, so a new check without a fault fails there.
#pragma once

#include "figures/figures.h"

#include <ostream>
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
      {"nguyen-1", F::ShadowLeftOut, "one fighter's shadow is cast onto the other"},
      {"nguyen-1", F::ShadowLeftOut, "the shadows also fall on the ring"},
      {"nguyen-2", F::ShadowLeftOut, "the projected polygons are the shadow"},
      {"nguyen-3", F::ShadowLeftOut, "planar edges stay sharp"},
      {"nguyen-3", F::PointSampled, "planar edges stay sharp"},
      {"nguyen-4", F::ShadowLeftOut, "the caster's shadow is drawn"},
      {"nguyen-4", F::FullStrength, "iterated alpha 170 leaves"},
      {"nguyen-4", F::ShadowLeftOut, "it climbs the step"},
      {"nguyen-5", F::EyeBesideLight, "the figure hides exactly the shadow it casts"},
      {"nguyen-6", F::EyeBesideLight, "the left panel is the receivers as the light sees them"},
      {"nguyen-6", F::FacingInverted, "lies on a triangle Listing 2 flags"},
      {"nguyen-7", F::StaleReadBack, "the texture holds only 0xF000"},
      {"nguyen-7", F::StaleReadBack, "its alpha is the caster's silhouette"},
      {"nguyen-7", F::NoCleanBorder, "clean border of at least two texels"},
      {"nguyen-8", F::StaleReadBack, "in the right panel"},
      {"nguyen-9", F::ShiftedProjection, "lands where the shadow truly is"},
      {"nguyen-10", F::TextureModeSwapped, "repeats its edge texels"},
      {"nguyen-11", F::TextureModeSwapped, "tiling repeats the texture"},
      {"nguyen-12", F::BorderIgnored, "the bug appears when the caster touches"},
      {"nguyen-12", F::NoCleanBorder, "the bug appears when the caster touches"},
      {"nguyen-13", F::BorderIgnored, "the clipped texture has silhouette texels"},
      {"nguyen-13", F::NoCleanBorder, "the fitted texture has none"},
      {"nguyen-14", F::SecondPassLess, "visible with a less-or-equal depth test"},
      {"nguyen-15", F::PointSampled, "alpha filtering gives many intermediate levels"},
      {"nguyen-16", F::WrongBuffer, "565: red in bits 15-11"},
      {"nguyen-16", F::WrongBuffer, "the shadow is drawn as 565 red"},
      {"nguyen-17", F::WrongFormat, "4444: alpha in bits 15-12"},
      {"nguyen-17", F::WrongFormat, "read as 4444 is alpha 1111b"},
      {"sgi-3", F::LightMoved, "the slide is projected onto the scene"},
      {"sgi-4", F::LightMoved, "the spotlight lights the scene through its map"},
      {"sgi-4", F::ShadowLeftOut, "both renderers' shadows match the ray-cast truth"},
      {"everitt-2", F::WrongBuffer, "samples closer to the light are darker"},
      {"everitt-2", F::ShadowLeftOut, "shadowed where the light is truly blocked"},
      {"everitt-4", F::ShadowLeftOut, "comparing the two gives the shadow"},
      {"everitt-5", F::PointSampled, "linear filtering blends the comparisons"},
  };
  return cases;
}

// How gtest names a case in its output: "nguyen-8: in the right panel".
inline void PrintTo(const FigureFaultCase &c, std::ostream *out) { *out << c.figure << ": " << c.claim; }

// True when some case names `figure` and a claim containing its words.
inline bool has_fault_case(const std::string &figure, const std::string &claim) {
  for (const FigureFaultCase &c : figure_fault_cases()) {
    if (figure == c.figure && claim.find(c.claim) != std::string::npos) return true;
  }
  return false;
}
