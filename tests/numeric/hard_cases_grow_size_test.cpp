// ProjectedShadowOptions::grow_to_accepted (--grow-size) on the fight at frames where the
// 256-texel shadow of a fighter is refused as too coarse for the screen (the demo's frames 41 and
// 90, 640x480, 12 frames a second; one fighter in 41, both in 90): with the mode, the shadow is
// drawn at the size the refusal names instead and is within the interior-error budget against
// the ray-cast truth; without it, the refusal is as it was. A shadow no size up to 512 would make fine enough is
// refused with the mode too, in the same words.
#include "hard_case_checks.h"

#include "scene/fight_scene.h"
#include "techniques/projected/projected_shadow.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// The demo's frame `index` (fight time index / 12 s).
gs::Scene fight_frame(int index) {
  gs::FightScene fight(640, 480, 256);
  return fight.at(static_cast<float>(index) / 12.0f);
}

// The fighters whose shadow a frame's refusals say is too coarse (texel_footprint_error).
std::vector<std::string> refused_as_too_coarse(const gs::Scene &scene, const Outcome &o) {
  std::vector<std::string> names;
  for (std::size_t fighter : gs::FightScene::kFighters) {
    const std::string names_them = "light 0 and '" + scene.objects[fighter].name + "': ";
    for (const std::string &e : o.refusals) {
      if (e.rfind(names_them, 0) == 0 && e.find("-texel shadow is too coarse") != std::string::npos) {
        names.push_back(scene.objects[fighter].name);
      }
    }
  }
  return names;
}

}  // namespace

TEST(HardCases, GrowSizeServesACoarseShadowAtTheAcceptedSize) {
  for (int index : {41, 90}) {
    const std::string what = "fight frame " + std::to_string(index) + ", projected 256";
    const gs::Scene scene = fight_frame(index);
    const Truth truth = truth_of(scene);
    ASSERT_GT(truth.shadow_pixels, 200) << what << ": no shadow, the case tests nothing";

    gs::TechniqueOptions plain;
    plain.projected.size = 256;
    const Outcome refused = run("projected", scene, truth, plain);
    report(what, refused);
    expect_clean_glide(what, refused);
    const std::vector<std::string> coarse = refused_as_too_coarse(scene, refused);
    ASSERT_FALSE(coarse.empty()) << what << ": accepted, the case tests nothing";
    EXPECT_EQ(refused.refusals.size(), coarse.size()) << what << ": a refusal of another kind";
    for (const std::string &e : refused.refusals) {
      EXPECT_NE(e.find("the 256-texel shadow is too coarse for the screen (size 512 would be "
                       "accepted); it casts no shadow from this light"),
                std::string::npos)
          << e;
    }

    gs::TechniqueOptions grown = plain;
    grown.projected.grow_to_accepted = true;
    const Outcome served = run("projected", scene, truth, grown);
    report(what + " --grow-size", served);
    expect_clean_glide(what + " --grow-size", served);
    EXPECT_TRUE(served.refusals.empty()) << what << ": " << served.refusals.front();
    for (const std::string &name : coarse) {
      EXPECT_EQ(gs::grown_shadow_size(served.warnings, 0, name), 512) << what << ": " << name;
    }
    EXPECT_LE(served.errors.false_shadow_interior + served.errors.false_light_interior,
              kInteriorBudget)
        << what;
    // The refused fighters' shadows are there: more pixels are darkened than without them.
    EXPECT_GT(served.shadowed, refused.shadowed) << what;
  }
}

TEST(HardCases, GrowSizeLeavesARefusalNoSizeFixes) {
  // A footprint limit of one screen pixel: the fighters' texels span about 5 at 256, 2.5 at 512.
  const gs::Scene scene = fight_frame(41);
  const Truth truth = truth_of(scene);
  gs::TechniqueOptions strict;
  strict.projected.size = 256;
  strict.projected.largest_texel_footprint_px = 1.0f;
  const Outcome refused = run("projected", scene, truth, strict);
  ASSERT_FALSE(refused.refusals.empty());
  for (const std::string &e : refused.refusals) {
    EXPECT_NE(e.find("no size up to 512 would be accepted"), std::string::npos) << e;
  }
  strict.projected.grow_to_accepted = true;
  const Outcome still = run("projected", scene, truth, strict);
  EXPECT_EQ(still.refusals, refused.refusals);
  EXPECT_EQ(still.mask, refused.mask);
}
