// Issue 14: the depth map served the twelfth audit's near-extra-lights_18628 with 0.168% of the
// receiver pixels as interior error (false light). An open bowl passes through box0, and lights 3
// and 4 stand on either side of it, so each one's shadow on box0 starts at the cut, on opposite
// sides: the truth is shadow across it. Each map's biases leave its shadow a pixel short of the
// cut, within that light's edge band alone, but the frame's mask is both shadows at once and
// has no edge there, so the lit seam between them is interior error. The estimate beside the
// caster's feet (depth_map_contacts.cpp) missed it twice: its camera rays took the bowl's back
// faces as hiding the receiver (the scene pass culls them), and it excused the band of a foot
// whose other side the frame has in shadow too.
// And it served planar19_camera_5cm with 0.119%: the floor seen from 5 cm above it is one row of
// pixels, crumple_loose's shadow edge runs nearly along it, and a fraction of a texel's stray
// across the edge moved its crossing 4 px along the row, 2 of them interior (the frame's budget
// is 1.7 px), against an edge estimate of 0 (its band, 2 px across the edge, covers the whole
// row). On a receiver seen as a strip under 3 px thick, the lookup is now replayed at the strip's
// own pixel centres (depth_map_strips.h). Scenes in tests/hard_cases/audit (dm20_*;
// tests/hard_cases/README.md).
#include "hard_case_checks.h"

#include <gtest/gtest.h>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// The depth map on `file`: served within the budget, or refused naming a light and `caster`.
// The frame holds more than `least_shadow` shadowed pixels (the floor strips' frames hold under
// 200, fewer than expect_these_right_or_refused asks for).
void expect_depth_map_right_or_refused(const std::string &file, const std::string &caster,
                                       long least_shadow = 150) {
  const gs::Scene scene = load(file);
  const Truth truth = truth_of(scene);
  ASSERT_GT(truth.shadow_pixels, least_shadow) << file << ": no shadow, the case tests nothing";
  const Outcome o = run("depth-map", scene, truth);
  report(file + " depth-map", o);
  expect_clean_glide("depth-map", o);
  if (!o.refusals.empty()) {
    for (const std::string &e : o.refusals) {
      EXPECT_EQ(e.rfind("light ", 0), 0u) << file << ": " << e;
      EXPECT_NE(e.find("and '" + caster + "'"), std::string::npos) << file << ": " << e;
    }
    return;
  }
  EXPECT_LE(o.errors.false_shadow_interior + o.errors.false_light_interior, kInteriorBudget)
      << file;
}

// Before: 0.168% (the audit's scene), 0.189% (320x240), 0.168% (lights 3 and 4 alone), 0.161%
// (box0 moved 5 cm), 0.201% (the camera nearer), all served. Now refused by name.
TEST(HardCases, DepthMapSeamBetweenTwoLightsShadowsAtASheetsCutIsRightOrRefused) {
  for (const char *file : {"audit/dm20_sheet_cut_audit18628.json", "audit/dm20_sheet_cut_320x240.json",
                           "audit/dm20_sheet_cut_two_lights.json", "audit/dm20_sheet_cut_box_moved.json",
                           "audit/dm20_sheet_cut_camera_closer.json"}) {
    expect_depth_map_right_or_refused(file, "bowl_loose");
  }
}

// Each of the two lights alone: its gap at the cut is its own edge's band, right (0.000%) and
// served before and after; the estimate must not refuse it.
TEST(HardCases, DepthMapShadowStartingAtASheetsCutUnderOneLightIsServed) {
  for (const char *file : {"audit/dm20_sheet_cut_light3_alone.json", "audit/dm20_sheet_cut_light4_alone.json"}) {
    const gs::Scene scene = load(file);
    const Truth truth = truth_of(scene);
    const Outcome o = run("depth-map", scene, truth);
    report(std::string(file) + " depth-map", o);
    EXPECT_TRUE(o.refusals.empty()) << file << ": " << (o.refusals.empty() ? "" : o.refusals[0]);
    EXPECT_LE(o.errors.false_shadow_interior + o.errors.false_light_interior, kInteriorBudget)
        << file;
  }
}

// A floor seen from 5 cm above it, one row of pixels: before, 0.119% served on both (the
// audit family's scene and the camera turned 0.3 m to +x at its target). Now refused naming
// crumple_loose.
TEST(HardCases, DepthMapShadowEdgeAlongAFloorStripIsRightOrRefused) {
  for (const char *file : {"audit/planar19_camera_5cm.json", "audit/dm20_floor_strip_5cm_turned.json"}) {
    expect_depth_map_right_or_refused(file, "crumple_loose", 20);
  }
}

// The strips' replay refuses only what it finds wrong: the camera 4 cm up, and 5 cm with the
// light 0.5 m to -x, are within the budget (0.000% and 0.056%) and served, before and after.
TEST(HardCases, DepthMapShadowOnAFloorStripWithinTheBudgetIsServed) {
  for (const char *file : {"audit/dm20_floor_strip_camera_4cm.json", "audit/dm20_floor_strip_5cm_light_west.json"}) {
    const gs::Scene scene = load(file);
    const Truth truth = truth_of(scene);
    ASSERT_GT(truth.shadow_pixels, 20) << file << ": no shadow, the case tests nothing";
    const Outcome o = run("depth-map", scene, truth);
    report(std::string(file) + " depth-map", o);
    EXPECT_TRUE(o.refusals.empty()) << file << ": " << (o.refusals.empty() ? "" : o.refusals[0]);
    EXPECT_LE(o.errors.false_shadow_interior + o.errors.false_light_interior, kInteriorBudget)
        << file;
  }
}

}  // namespace
