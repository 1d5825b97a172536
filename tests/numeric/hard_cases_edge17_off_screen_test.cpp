// Issue 14: a floating wall's shadow thrown far along a floor (the light between the wall's
// bottom and top, as tests/hard_cases/audit/ne1 and ne2), with the camera turned so that the
// shadow runs off a side of the screen. The estimate of the error along the shadow's edges
// (src/techniques/texel_error/shadow_edge_error.h) took each receiver polygon as the screen
// clips it, so it followed a shadow edge only as far as the screen's side: where the true edge
// lies off the screen, it counted nothing, while the 128-texel texture's edge strayed onto the
// screen over pixels no true edge excuses. Scenes tests/hard_cases/audit/edge17_* (their README
// and tests/hard_cases/README.md): before, the projected techniques served them with 0.465% and
// 0.476% (below the screen), 0.188% and 0.198% (right side) and 0.106% and 0.113% (corner)
// interior error; now both refuse them by name, and at the size named (256) both are right.
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

const char *const kOffScreenWalls[] = {"audit/edge17_wall_shadow_below_screen_map128.json",
                                       "audit/edge17_wall_shadow_off_right_side_map128.json",
                                       "audit/edge17_wall_shadow_off_corner_map128.json"};

// Interior error (both kinds) as a share of the counted receiver pixels.
double interior(const Outcome &o) {
  return o.errors.false_shadow_interior + o.errors.false_light_interior;
}

}  // namespace

// The projected techniques refuse naming the light, the wall and 256 texels; the others serve
// within the budget. Two of the scenes have no true shadow on the screen at all, so every wrong
// pixel there is interior error (expect_right_or_refused asks for a shadow to look at).
TEST(HardCases, WallShadowRunningOffTheScreenIsRightOrRefused) {
  for (const char *file : kOffScreenWalls) {
    const gs::Scene scene = load(file);
    const Truth truth = truth_of(scene);
    for (const std::string &name : kTechniques) {
      const Outcome o = run(name, scene, truth);
      report(std::string(file) + " " + name, o);
      expect_clean_glide(name, o);
      if (name == "projected" || name == "projected-chroma") {
        ASSERT_FALSE(o.refusals.empty()) << file << " " << name << ": should refuse at 128 texels";
        EXPECT_NE(o.refusals[0].find("light 0 and 'wall': the shadow texels would move its edges"),
                  std::string::npos)
            << o.refusals[0];
        EXPECT_NE(o.refusals[0].find("size 256 would be accepted"), std::string::npos)
            << o.refusals[0];
        continue;
      }
      for (const std::string &e : o.refusals) ADD_FAILURE() << file << " " << name << ": " << e;
      EXPECT_LE(interior(o), kInteriorBudget) << file << " " << name;
    }
  }
}

// At the size the refusals name, both projected techniques serve the frame within the budget:
// the refusal at 128 texels was the texels' doing, not a blanket one.
TEST(HardCases, WallShadowRunningOffTheScreenIsRightAtTheSizeNamed) {
  for (const char *file : kOffScreenWalls) {
    gs::Scene scene = load(file);
    for (gs::SpotLight &light : scene.lights) light.shadow_size = 256;
    const Truth truth = truth_of(scene);
    for (const std::string &name : kProjectedTechniques) {
      const Outcome o = run(name, scene, truth);
      report(std::string(file) + " " + name + " at 256 texels", o);
      EXPECT_TRUE(o.refusals.empty()) << file << " " << name << ": " << o.refusals[0];
      EXPECT_LE(interior(o), kInteriorBudget) << file << " " << name << " at 256 texels";
    }
  }
}
