// Issue 14, the sixteenth audit's near-camera-near-edge_23361: stencil volume 0.629% interior
// false light served (0.754% for the stencil volume and the depth map on its reduction). A gobo
// bar's edge crosses a slab's shadow on dunes under a 162.7-degree cone, seen from a camera 28 cm
// above them. The plain-GL masks gate their shadow by the light's footprint on its beam plane
// (plain_gl/gl_beam_mask.cpp), a 1024-texel texture cut at 1/2 after bilinear filtering; with 0
// or 1 in its texels the cut fell halfway between texel centres, up to half a texel from the
// bar's edge, which the wide cone stretches to 5 or 6 mm on the dunes and the close camera to 4
// pixels. The texels now hold 1/2 plus a third of their signed distance (texels) to the lit
// region's edge, so the cut falls on the edge. Scenes in tests/hard_cases/audit (beam23_*; README,
// "A beam's edge cut between texel centres").
#include "hard_case_checks.h"

#include <gtest/gtest.h>

using namespace hard_cases;  // the checks of hard_case_checks.h

// The audit's reduction (dunes, slab, the gobo light), the camera moved 14 cm nearer the edge,
// and zoomed to 40 degrees at 480x360: 0.754%, 0.673% and 1.949% interior false light for the
// stencil volume and the depth map before.
TEST(HardCases, GoboBarEdgeSeenCloseUnderAWideCone) {
  for (const char *file : {"audit/beam23_gobo_bar_edge_close.json",
                           "audit/beam23_gobo_bar_edge_closer.json",
                           "audit/beam23_gobo_bar_edge_close_zoomed.json"}) {
    expect_right_or_refused(file);
  }
}

// The same under a 150-degree cone, where the bar's edge falls elsewhere on the dunes (0.008%
// before: within the budget, 0.000% after).
TEST(HardCases, GoboBarEdgeUnderANarrowerCone) {
  expect_right_or_refused("audit/beam23_gobo_cone150.json");
}
