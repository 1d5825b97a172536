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

#include <algorithm>
#include <memory>
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
std::vector<std::size_t> refused_as_too_coarse(const gs::Scene &scene, const Outcome &o) {
  std::vector<std::size_t> fighters;
  for (std::size_t fighter : gs::FightScene::kFighters) {
    const std::string names_them = "light 0 and '" + scene.objects[fighter].name + "': ";
    for (const std::string &e : o.refusals) {
      if (e.rfind(names_them, 0) == 0 && e.find("-texel shadow is too coarse") != std::string::npos) {
        fighters.push_back(fighter);
      }
    }
  }
  return fighters;
}

// The sizes the projected technique drew the frame's shadows at (FrameReport::shadow_sizes),
// from a render of `scene` of its own, as hard_case_checks.h's run() renders it.
std::vector<gs::DrawnShadowSize> drawn_sizes(const gs::Scene &scene,
                                             const gs::TechniqueOptions &options) {
  std::string error;
  const std::unique_ptr<gs::ShadowTechnique> technique = gs::make_technique("projected", options, error);
  EXPECT_TRUE(technique) << error;
  if (!technique) return {};
  grGlideInit();
  EXPECT_TRUE(glideShimSetWindowSize(scene.width, scene.height));
  EXPECT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1))
      << glideShimGetLastErrorMessage();
  const gs::FrameReport frame = technique->render(scene, false);
  grGlideShutdown();
  return frame.shadow_sizes;
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
    const std::vector<std::size_t> coarse = refused_as_too_coarse(scene, refused);
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
    // Each refused fighter's shadow drawn at 512 (the size the refusal named), the other's at
    // 256 as without the mode; and a note says so for each one grown.
    const std::vector<gs::DrawnShadowSize> sizes = drawn_sizes(scene, grown);
    for (std::size_t fighter : gs::FightScene::kFighters) {
      const bool was_coarse = std::find(coarse.begin(), coarse.end(), fighter) != coarse.end();
      const std::string &name = scene.objects[fighter].name;
      EXPECT_EQ(gs::drawn_shadow_size(sizes, 0, fighter), was_coarse ? 512 : 256)
          << what << ": " << name;
      const std::string note = "light 0 and '" + name + "': ";
      EXPECT_EQ(std::count_if(served.warnings.begin(), served.warnings.end(),
                              [&](const std::string &w) {
                                return w.rfind(note, 0) == 0 &&
                                       w.find("; its shadow is drawn at 512 texels instead") !=
                                           std::string::npos;
                              }),
                was_coarse ? 1 : 0)
          << what << ": " << name;
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
