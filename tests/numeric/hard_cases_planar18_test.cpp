// Issue 14: the planar technique's seals over a nearer receiver. Each shadow polygon is drawn as a
// cover a few W codes above its receiver and a seal above that, so that a pixel darkens once per
// light. The seal stood 16 codes above the cover (and, over a receiver the shim clipped to the
// window, 1/8 px of its depth gradient more): where another receiver lay in front of the polygon's
// receiver but within that reach, the seal passed it and wrote its depth, and the nearer
// receiver's own cover of the same light then failed, leaving false light:
//   - along the line where two receivers cross (two boards that cast nothing, under a plate's
//     shadow; one part of a fighter passing into another, seen from inside a ball round its head:
//     stencil17_sv4, 0.105% of the receiver pixels);
//   - along the edges of dune triangles seen edge-on just in front of a cylinder at the bottom of
//     the screen, the camera under the dunes (the eleventh audit's
//     sunk-extra-lights-narrow-cones-camera-behind_17248, 0.306%).
// The seal now stands half a code above its cover, less than any cover's margin, and covers and
// seals are clipped to the window with their depths on the plane (planar_shadow.cpp). Scenes in
// tests/hard_cases/audit (planar18_*; tests/hard_cases/README.md).
// And the hidden regions (planar_hidden.cpp) of a caster cut by the camera's near plane: its part
// nearer than the near plane, which the scene pass clipped away, was taken to hide the receiver
// planes it passes through, and the shadow there was left out (sv18's hut, the camera outside its
// wall seeing in: the post's sides inside, in the roof's shadow, left lit, 4.46%).
#include "hard_case_checks.h"

#include <gtest/gtest.h>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// Every technique right on the crossing boards (0.151%, 0.161% and 0.900% interior for planar
// before).
TEST(HardCases, PlanarShadowOnCrossingReceiversIsRight) {
  for (const char *file : {"audit/planar18_boards_crossing_6deg_under_plate.json",
                           "audit/planar18_boards_crossing_12deg_under_plate.json",
                           "audit/planar18_boards_crossing_3deg_side_view.json"}) {
    expect_right_or_refused(file);
  }
}

// The fighter's own parts crossing in the ball's shadow. Only planar is asked: the stencil
// volume is stencil17's test's, and the others refuse it by name there.
TEST(HardCases, PlanarShadowOnAFighterSeenFromInsideABallIsRight) {
  const char *file = "audit/stencil17_sv4_camera_in_ball_round_fighters_head.json";
  expect_these_right_or_refused(file, load(file), {"planar"}, {}, true);
}

// The camera under the dunes (their back faces culled) looking up at a cylinder sunk in them:
// every technique right or refused by name (the chroma key's 128-texel map is too coarse for the
// dunes of the audit's scene; the stencil volume cannot close the open cylinder). The projected
// techniques' refusals here are spill19's cost: the edge-error estimate counts the stray along a
// caster's cut through the masking dunes, which does not show in these frames (0.024%, 0.023%
// and 0.046% served before). On the closer view only planar is asked: the projected techniques
// refuse it (spill19's test).
TEST(HardCases, PlanarShadowOnACylinderSeenUpThroughDunesIsRight) {
  expect_right_or_refused("audit/planar18_cylinder_under_dunes_box_shadow_audit17248.json",
                          {{"projected", "light 1 and 'box1'"},
                           {"projected-chroma", "too coarse"},
                           {"stencil-volume", "is not a closed mesh"}},
                          false);
  expect_right_or_refused("audit/planar18_cylinder_under_dunes_taller_dunes.json",
                          {{"projected", "'cylinder2'"},
                           {"projected-chroma", "'cylinder2'"},
                           {"stencil-volume", "is not a closed mesh"}},
                          false);
  const char *close = "audit/planar18_cylinder_under_dunes_sphere_shadow_close.json";
  expect_these_right_or_refused(close, load(close), {"planar"}, {}, false);
}

// The camera outside the hut, its near plane cutting into the wall, seeing the post inside in
// the roof's shadow (4.461% and 1.143% interior for planar before). Only planar is asked: the
// depth map serves both over the budget (0.511% and 0.336%), which is its to answer.
TEST(HardCases, PlanarShadowSeenThroughAWallCutByTheNearPlaneIsRight) {
  for (const char *file : {"audit/sv18_near_plane_in_hut_post_through_roof.json",
                           "audit/planar18_near_plane_in_hut_level_look_thin_post.json"}) {
    expect_these_right_or_refused(file, load(file), {"planar"}, {}, true);
  }
}

}  // namespace
