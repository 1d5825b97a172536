// Issue 14, strip19: the projected techniques on a floor seen from a camera 7 and 10 cm above it
// at 160x120 (tests/hard_cases/README.md, "A floor seen from a few centimetres above it").
// The wrong pixel is not on the floor: it lies on the crumpled sheet, where two of its faces
// fold away from the camera. fighter1's true shadow there is a sliver that holds no pixel
// centre; the 64-texel texture's edge reaches one centre 1.8 px from it, and with no true
// shadow pixel beside it that pixel is interior error. The frame's receivers are under 1,000
// pixels (the error measure counts 89 and 481; the budget's base 487 and 513), so 0.1% is under
// one pixel and that one pixel is 1.119% and 0.208%; the edge-error estimate said 0.005 px.
// A frame whose budget is under one pixel now accepts no estimated stray at all, and both
// projected techniques refuse the shadow naming light 0 and the caster whose estimate is not 0.
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// Each projected technique refuses the shadow of `caster` from light 0 on `file` (its first
// refusal: the casters are checked in the scene's order).
void expect_projected_refused_naming(const std::string &file, const std::string &caster) {
  const gs::Scene scene = load(file);
  const Truth truth = truth_of(scene);
  ASSERT_GT(truth.shadow_pixels, 20) << file << ": no shadow, the case tests nothing";
  for (const std::string &name : kProjectedTechniques) {
    const Outcome o = run(name, scene, truth);
    report(file + " " + name, o);
    expect_clean_glide(name, o);
    ASSERT_FALSE(o.refusals.empty()) << file << " " << name << ": should refuse, not pass";
    EXPECT_NE(o.refusals[0].find("light 0 and '" + caster + "'"), std::string::npos)
        << o.refusals[0];
  }
}

}  // namespace

// Before: 1.119% interior (one pixel of 89), both projected techniques, served.
TEST(HardCases, ProjectedOnAFloorStripSevenCentimetresBelowTheCameraIsRefused) {
  expect_projected_refused_naming("audit/planar19_camera_7cm_160x120.json", "fighter1");
}

// Before: 0.208% (one pixel of 481), both, served. crumple_loose comes first in the scene and
// its estimate (0.034 px) is over the frame's budget of none.
TEST(HardCases, ProjectedOnAFloorStripTenCentimetresBelowTheCameraIsRefused) {
  expect_projected_refused_naming("audit/planar19_camera_10cm_160x120.json", "crumple_loose");
}
