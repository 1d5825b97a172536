// Issue 14, spill19: a cylinder sunk in dunes that cast nothing, seen from under them next to
// the dune triangle it passes through (tests/hard_cases/README.md, "The cut through a masking
// surface"). The cylinder's texture is masked by the dunes' surface; step 1's contact strips
// beside its cut were dropped, so the texture's edge at the cut strays onto the lit dune the
// camera sees, and the edge-error estimate did not count the cut (0 px against 2.66): both
// projected techniques served 0.11 to 0.23% interior error. Now the cut is a contact edge of
// the estimate, and the frame is refused naming light 0 and 'cylinder2'.
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// Each projected technique serves `file` within the budget, or refuses it naming light 0 and
// `caster`.
void expect_projected_right_or_refused_naming(const std::string &file, const std::string &caster) {
  expect_these_right_or_refused(file, load(file), kProjectedTechniques, {}, true,
                                Leeway{150, "light 0 and '" + caster + "'"});
}

}  // namespace

// Before: 0.151% (projected) and 0.227% (projected-chroma) interior, served.
TEST(HardCases, ProjectedCylinderCutThroughASeenDuneIsRightOrRefused) {
  expect_projected_right_or_refused_naming(
      "audit/planar18_cylinder_under_dunes_sphere_shadow_close.json", "cylinder2");
}

// Before: 0.187% and 0.187%.
TEST(HardCases, ProjectedCylinderCutThroughASeenDuneCameraCloserIsRightOrRefused) {
  expect_projected_right_or_refused_naming("audit/spill19_dunes_cut_camera_closer.json",
                                           "cylinder2");
}

// Before: 0.151% and 0.227%; and 0.113% and 0.151% with the light turned the other way.
TEST(HardCases, ProjectedCylinderCutThroughASeenDuneLightTurnedIsRightOrRefused) {
  expect_projected_right_or_refused_naming("audit/spill19_dunes_cut_light_turned_plus3.json",
                                           "cylinder2");
  expect_projected_right_or_refused_naming("audit/spill19_dunes_cut_light_turned_minus3.json",
                                           "cylinder2");
}

// Before: 0.148% and 0.233% at 320x240.
TEST(HardCases, ProjectedCylinderCutThroughASeenDuneLargerScreenIsRightOrRefused) {
  expect_projected_right_or_refused_naming("audit/spill19_dunes_cut_screen_320.json", "cylinder2");
}

// The twelfth audit's meshes_18307: an open bowl half-buried in the dunes under a low light. Its
// faces turned from the light are drawn too (an open caster), and their cut through the dunes
// strays as the others do. Before: 0.111% and 0.122% at 880e870 (0.171% and 0.185% at
// 6a07ceb); at 128 texels 0.204% and 0.212%.
TEST(HardCases, ProjectedOpenBowlHalfBuriedInDunesIsRightOrRefused) {
  expect_projected_right_or_refused_naming("audit/spill19_bowl_half_buried_audit18307.json",
                                           "bowl0_loose");
  expect_projected_right_or_refused_naming("audit/spill19_bowl_half_buried_128_texels.json",
                                           "bowl0_loose");
}
