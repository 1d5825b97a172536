// Issue 14: the planar technique on a floor seen from a camera a few centimetres above it (the
// twelfth audit's near-camera-behind_18652, planar 0.150% of the receiver pixels as interior
// error). The floor is a strip a few pixels tall, squeezed to about 1% of its width, so every
// shadow edge on it runs nearly level along the rows. Step 3 drew each shadow polygon with its
// corners snapped to 1/16 px: box0's shadow, a sliver 0.3 px tall whose far edge ran within
// 0.03 px of its row's pixel centres, lost 8 of its 14 pixels on the strip's top row, which no
// neighbour marks as an edge's band (the sky above). The polygons are now drawn a row of pixel
// centres at a time, each run a rectangle on pixel boundaries, cut to the pixels their receiver
// triangle drew (planar_rows.h). Scenes in tests/hard_cases/audit (planar19_*;
// tests/hard_cases/README.md).
#include "hard_case_checks.h"

#include <gtest/gtest.h>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// Planar within the budget, not refusing, on `file`. These frames hold 25 to 179 shadowed
// pixels (the floor is a strip), so each pixel weighs 0.05% to 0.25% of the receiver pixels,
// and 0.1% is one or two of them.
void expect_planar_right(const std::string &file) {
  expect_these_right_or_refused(file, load(file), {"planar"}, {}, true, Leeway{20, ""});
}

// The audit's scene and its variants: camera 5 to 12 cm above the floor, 160x120 and 320x240,
// the light moved. Planar's interior error before: 0.150% (the audit's scene), 0.208% and
// 1.119% (160x120 at 10 and 7 cm), 0.311% and 0.284% (7 cm, the light moved west, north-east),
// 0.059% (5 cm), 0.000% (12 cm). Only planar is asked: the projected techniques, which served
// the 160x120 scenes over the budget (0.208% and 1.119%), refuse them by name now
// (hard_cases_tiny20_test.cpp).
TEST(HardCases, PlanarShadowOnAFloorSeenFromCentimetresAboveIsRight) {
  for (const char *file : {"audit/planar19_camera_10cm_audit18652.json",
                           "audit/planar19_camera_10cm_160x120.json",
                           "audit/planar19_camera_7cm_160x120.json",
                           "audit/planar19_camera_7cm_light_west.json",
                           "audit/planar19_camera_7cm_light_northeast.json",
                           "audit/planar19_camera_5cm.json", "audit/planar19_camera_12cm.json"}) {
    expect_planar_right(file);
  }
}

}  // namespace
