// The projected shadow's textures: a clean border in every demo frame, the LFB and direct paths
// giving the same bytes, a 512 map as four Voodoo textures, and textures beyond TMU memory
// loaded in turn.
#include "context.h"
#include "scene/fight_scene.h"
#include "techniques/projected/projected_shadow.h"

#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include "projected_shadow_fixture.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace {

TEST_F(ProjectedShadowTest, TextureKeepsACleanBorderInEveryDemoFrame) {
  gs::FightScene fight(kWidth, kHeight, 128);
  gs::ProjectedShadowOptions options;
  options.size = 128;
  for (float time : {0.0f, 1.0f, 2.1f, 4.0f, 5.3f, 7.0f}) {
    const gs::Scene &scene = fight.at(time);
    const gs::ShadowFrame frame = gs::render_projected_shadows(scene, options, false);
    // A texture per fighter, and one more per receiver it reaches through (its soles into the
    // mat's relief, pierced_receivers.h): each keeps the border.
    ASSERT_GE(frame.jobs.size(), 2u) << "time " << time;
    for (const std::size_t fighter : gs::FightScene::kFighters) {
      EXPECT_TRUE(std::any_of(frame.jobs.begin(), frame.jobs.end(),
                              [&](const gs::ShadowJob &job) { return job.caster == fighter; }))
          << "time " << time << ": fighter " << fighter << " has no texture";
    }
    for (const gs::ShadowJob &job : frame.jobs) {
      const auto *words = reinterpret_cast<const FxU16 *>(glide_shim::current().tmu.memory.data() +
                                                          job.texture.address);
      int drawn = 0, border = 0;
      for (int y = 0; y < 128; ++y) {
        for (int x = 0; x < 128; ++x) {
          const bool set = words[y * 128 + x] != 0;
          drawn += set;
          border += set && (x < 2 || y < 2 || x >= 126 || y >= 126);
        }
      }
      // A fighter's texture for the other fighter it reaches into holds only what lies nearer
      // the light than that fighter's surface and its outline's fins (pierced_surfaces.cpp):
      // 499 texels at t = 4 (636 before the fins), the whole fighter about 1,900. The one for
      // the parts of the other fighter that fighter's own surface hides from the light
      // (SurfaceMask::farthest) holds the caster only over that fighter's farthest surface:
      // 58 texels at t = 4, 10 at t = 5.3.
      EXPECT_GT(drawn, job.mask_farthest ? 0 : 400) << "time " << time << ": caster missing from its texture";
      EXPECT_EQ(border, 0) << "time " << time << ": caster touches the texture's border";
    }
  }
}

// 128 texels: at 64, the edge-error estimate refuses the blue fighter's shadow at 0.5 s (its
// edges followed past the screen's sides since edge17), and a refused shadow has no texture.
TEST_F(ProjectedShadowTest, LfbAndDirectPathsGiveIdenticalTextures) {
  constexpr int kSize = 128;
  gs::FightScene fight(kWidth, kHeight, kSize);
  for (float time : {0.5f, 2.1f, 5.3f}) {
    const gs::Scene &scene = fight.at(time);
    std::vector<std::vector<std::uint8_t>> textures[2];
    for (int direct = 0; direct < 2; ++direct) {
      gs::ProjectedShadowOptions options;
      options.size = kSize;
      options.direct_path = direct == 1;
      const gs::ShadowFrame frame = gs::render_projected_shadows(scene, options, false);
      EXPECT_TRUE(frame.errors.empty()) << "time " << time << ": " << frame.errors.front();
      for (const gs::ShadowJob &job : frame.jobs) {
        const std::uint8_t *bytes = glide_shim::current().tmu.memory.data() + job.texture.address;
        textures[direct].emplace_back(bytes, bytes + kSize * kSize * 2);
      }
    }
    // A fighter's, and one per receiver it reaches through; none for a receiver wholly nearer
    // the light than the fighter (the other fighter at 2.1 s: caster_surface_from_light.h).
    ASSERT_GE(textures[0].size(), time == 2.1f ? 1u : 2u);
    EXPECT_TRUE(textures[0] == textures[1]) << "time " << time;
  }
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

TEST_F(ProjectedShadowTest, A512MapIsFourVoodooTexturesThatShadowLikeOne) {
  // A Voodoo 1 texture is at most 256x256: a 512 map is drawn as four tiles, and the shadow they
  // cast together is the one map's (up to edge resolution), with no seam left unshadowed.
  const gs::Scene scene = box_over_floor();
  gs::ProjectedShadowOptions one, tiled;
  tiled.size = 512;
  gs::ShadowFrame frame;
  const std::vector<bool> tiled_mask = shadow_mask(scene, tiled, &frame);
  EXPECT_EQ(frame.jobs.size(), 4u);
  const std::vector<bool> one_mask = shadow_mask(scene, one);
  int tiled_count = 0, one_count = 0;
  for (bool b : tiled_mask) tiled_count += b;
  for (bool b : one_mask) one_count += b;
  EXPECT_GT(one_count, 200);
  EXPECT_GE(count(tiled_mask, one_mask), one_count * 95 / 100) << "tiles leave part of the shadow out";
  EXPECT_LE(tiled_count, one_count * 105 / 100) << "tiles shadow more than the map";
}

TEST_F(ProjectedShadowTest, TexturesBeyondTmuMemoryAreLoadedInTurn) {
  // 20 casters at 256x256 ARGB_4444 need 2.5 MB; the TMU has 2 MB: step 2 places 16, and the
  // other 4 are loaded (step 1 drawn again on the direct path) over textures already drawn with
  // as step 5 and the mask pass come to them.
  const gs::ShadowFrame frame = expect_the_union_of_halves(boxes_in_a_row(19));
  EXPECT_TRUE(frame.textures_loaded);
}

TEST_F(ProjectedShadowTest, AShadowTextureWhereTheBeamMapGoesIsLoadedAgain) {
  // A beam map's scene pass downloads its texture at 1.5 MB (kProjectiveTextureAddress), where
  // the 13th 256-texel shadow texture lies: 14 casters, which all fit, and that one is loaded
  // again after the scene pass.
  gs::Scene scene = boxes_in_a_row(13);
  scene.lights[0].beam = "round";
  const gs::ShadowFrame frame = expect_the_union_of_halves(scene);
  EXPECT_TRUE(frame.textures_loaded);
}

}  // namespace
