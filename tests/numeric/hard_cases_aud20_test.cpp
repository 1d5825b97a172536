// Issue 14, aud20: the eleventh audit's near_17122 (projected 0.121% interior false shadow,
// served). Light 1 stands 0.93 m behind a floating prism on the camera's side, so the prism's
// shadow edge on the dunes lies behind the prism as the camera sees it: the true edge is hidden
// and no band of it excuses the pixels beside the prism's outline, where the 64-texel texture's
// edge strays out from under the prism onto the lit dune (two streaks of false shadow). The
// edge-error estimate excused every edge it could not see as if it were seen (2 px of band).
// Now a sample of a shadow edge that the caster's lit face along it hides from the camera has
// no band, and what strays out to where the camera sees it past that face counts
// (texel_error/shadow_edge_error.cpp): the frame is refused naming the light and 'prism'.
// Scenes in tests/hard_cases/audit (aud20_*; README, "A shadow edge the caster hides (aud20)").
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// Each projected technique serves `file` within the budget, or refuses it naming `light` (as
// "light N") and 'prism'. More than 150 shadow pixels; two lights, so only_in_beam is off
// (shadow_where_unlit asks light 0 alone).
void expect_prism_right_or_refused_naming(const std::string &file, const std::string &light) {
  expect_these_right_or_refused(file, load(file), kProjectedTechniques, {}, false,
                                Leeway{151, light + " and 'prism'"});
}

}  // namespace

// The audit's frame (320x240, two lights): projected 0.121% served before (12 px of false
// shadow beside the prism); the chroma key refuses for its texels' footprint before and after.
TEST(HardCases, PrismHidingItsShadowEdgeIsRightOrRefused) {
  expect_prism_right_or_refused_naming("audit/aud20_prism_hides_edge_audit17122.json",
                                           "light 1");
}

// Light 1 alone (it is light 0 then): 0.151% served before.
TEST(HardCases, PrismHidingItsShadowEdgeOneLightIsRightOrRefused) {
  expect_prism_right_or_refused_naming("audit/aud20_prism_hides_edge_light1_only.json",
                                           "light 0");
}

// 160x120: both projected techniques 0.121% served before.
TEST(HardCases, PrismHidingItsShadowEdgeAt160x120IsRightOrRefused) {
  expect_prism_right_or_refused_naming("audit/aud20_prism_hides_edge_screen160.json",
                                           "light 1");
}

// The camera 1.3 times as far: projected right (0.032%) before and after, and still served:
// the hidden edge's strays mostly end behind the prism too, and do not count (two lights:
// only_in_beam off, as shadow_where_unlit asks light 0 alone).
TEST(HardCases, PrismHidingItsShadowEdgeCameraFartherStillServed) {
  const std::string file = "audit/aud20_prism_hides_edge_camera_farther.json";
  expect_these_right_or_refused(file, load(file), {"projected"}, {}, false);
}
