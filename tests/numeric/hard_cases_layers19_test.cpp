// Issue 14: a capped cylinder lying through dunes that cast, under a narrow cone 1.3 m up with a
// coarse map (the eleventh audit's sunk-narrow-cones_17223; tests/hard_cases/README.md, "layers19").
// Part of the cylinder lies between two layers of the dunes as the light sees them, which one
// texture cannot show: receiver_layers finds it from samples along the caster's edges, but at 64
// texels they were 4 of its texels (16 of a 256 view) apart and stepped over it, and the shadow
// was served with 0.113% interior error. The samples of a texture coarser than 256 are now
// split as a 256 view's would be, keeping its own, and the shadow on the dunes is refused by name.
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// The refusal receiver_layers_error gives, naming the light and the caster.
const std::map<std::string, std::string> kBetweenDunes = {
    {"projected", "light 0 and 'cylinder0': part of the caster lies between two parts of 'dunes'"},
    {"projected-chroma",
     "light 0 and 'cylinder0': part of the caster lies between two parts of 'dunes'"}};

}  // namespace

// Before: 0.113% / 0.123% served (nc1, the audit's scene, and nc2, the cylinder alone), 0.174% /
// 0.180% (nc3, 32 texels).
TEST(HardCases, CylinderBetweenCastingDuneLayersUnderCoarseMapIsRefused) {
  for (const char *file : {"audit/layers19_nc1_cylinder_through_casting_dunes_narrow_cone.json",
                           "audit/layers19_nc2_cylinder_alone_through_casting_dunes.json",
                           "audit/layers19_nc3_cylinder_through_casting_dunes_map32.json"}) {
    expect_these_right_or_refused(file, load(file), kProjectedTechniques, kBetweenDunes, true);
  }
}

// The light 0.3 m higher: no caster part between two layers; served right before and now.
TEST(HardCases, CylinderThroughCastingDunesUnderHigherLightStillServed) {
  expect_projected_right("audit/layers19_nc4_cylinder_through_casting_dunes_light_1_6m.json");
}
