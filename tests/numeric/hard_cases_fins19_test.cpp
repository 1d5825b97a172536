// Issue 14: the twelfth audit's sunk-camera-behind_18439 (projected and the chroma key 0.156%
// interior false shadow served). The camera is under the ring's mat looking up; capped cylinder1
// passes through the mat, and one long side of it (triangle 24) is nearly edge-on to the light
// (n.l = 0.003) and reaches out of the light's view. The ring's shadow on cylinder1 reads a
// texture masked by cylinder1's surface, whose outline fins kept the mat beyond the outline out
// of the texture only for triangles wholly inside the view: that side had none, and bilinear
// filtering put the mat's texels on its lit edge (a speck of false shadow near its silhouette).
// Fins are now drawn from such a triangle's unclipped corners when all lie beyond the caster's
// front (receiver_mask_surface.cpp, `draw_mask_surface`); these tests fail without them.
// Scenes in tests/hard_cases/audit (fins19_*; README, "Fins on a receiver leaving the light's view").
#include "hard_case_checks.h"

#include <gtest/gtest.h>

using namespace hard_cases;  // the checks of hard_case_checks.h

// Each: both projected techniques served within the budget, none refusing
// (`expect_projected_right`, which also asks for over 150 pixels of one object's shadow on
// another).

// The audit's frame (160x120, 256 texels, 2,559 receiver pixels): 0.156% served by both before
// the fins (2 pixels of false shadow and 2 of false light), 0.078% after (the 2 of false light,
// which the fins do not touch).
TEST(HardCases, FinsOnACylinderSideLeavingTheLightsView) {
  expect_projected_right("audit/fins19_cylinder_edge_on_to_light_audit18439.json");
}

// 512 texels: the speck grows, 0.274% served by both before.
TEST(HardCases, FinsOnACylinderSideLeavingTheLightsViewMap512) {
  expect_projected_right("audit/fins19_cylinder_edge_on_to_light_map512.json");
}

// 320x240: 0.156% and 0.166% (chroma) served before.
TEST(HardCases, FinsOnACylinderSideLeavingTheLightsViewAt320x240) {
  expect_projected_right("audit/fins19_cylinder_edge_on_to_light_320x240.json");
}
