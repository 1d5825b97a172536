// The projected shadow tests' fixture: a Glide window per test (TechniqueTest), the technique's
// shadow mask read back as pixels, and scenes of many casters with the check that their shadows
// are the union of each half's.
#pragma once

#include "techniques/projected/projected_shadow.h"

#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include "technique_fixture.h"

#include <string>
#include <vector>

class ProjectedShadowTest : public TechniqueTest {
 protected:
  // Which pixels the technique darkened (white in render_shadow_mask).
  static std::vector<bool> shadow_mask(const gs::Scene &scene, const gs::ProjectedShadowOptions &options,
                                       gs::ShadowFrame *out = nullptr) {
    const gs::ShadowFrame frame = gs::render_projected_shadows(scene, options, false);
    gs::render_shadow_mask(scene, options, frame);
    std::vector<bool> mask;
    for (FxU16 p : back_buffer()) mask.push_back(p != 0);
    if (out != nullptr) *out = frame;
    return mask;
  }

  // box_over_floor with `boxes` small boxes more in a row, standing apart: touching ones hide
  // each other's sides from the light, and each such pair takes one more texture
  // (receiver_layers.h).
  static gs::Scene boxes_in_a_row(int boxes) {
    gs::Scene scene = box_over_floor();
    for (int i = 0; i < boxes; ++i) {
      scene.objects.push_back(object(
          "box " + std::to_string(i), gs::make_box(glm::vec3(0.1f)),
          {-3.2f + 0.35f * static_cast<float>(i), 1.0f, 1.0f}));
    }
    return scene;
  }

  // Every caster of `scene` casts, one 256-texel texture each on the direct path, and each the
  // shadow it casts in a frame whose textures all fit: the mask is the union of the masks of the
  // first half of the casters alone and the second half alone, pixel for pixel (the mask pass
  // draws each texture alone). Returns the whole frame.
  static gs::ShadowFrame expect_the_union_of_halves(const gs::Scene &scene) {
    gs::ProjectedShadowOptions options;
    options.size = 256;
    options.direct_path = true;
    const std::size_t casters = scene.objects.size() - 1;  // all but the floor
    gs::ShadowFrame frame;
    const std::vector<bool> all = shadow_mask(scene, options, &frame);
    EXPECT_EQ(frame.jobs.size(), casters);
    EXPECT_TRUE(frame.errors.empty()) << frame.errors.front();
    EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
    std::vector<bool> halves(all.size(), false);
    for (int half = 0; half < 2; ++half) {
      gs::Scene part = scene;
      for (std::size_t k = 1; k < part.objects.size(); ++k) {
        part.objects[k].casts_shadow = (k <= casters / 2) == (half == 0);
      }
      gs::ShadowFrame part_frame;
      const std::vector<bool> mask = shadow_mask(part, options, &part_frame);
      EXPECT_EQ(part_frame.jobs.size(), half == 0 ? casters / 2 : casters - casters / 2);
      EXPECT_FALSE(part_frame.textures_loaded) << "half of them fit";
      for (std::size_t p = 0; p < mask.size(); ++p) halves[p] = halves[p] || mask[p];
    }
    EXPECT_GT(count(all), 1000);
    EXPECT_TRUE(all == halves) << count(all, halves) << " pixels in common of "
                               << count(all) << " and "
                               << count(halves);
    return frame;
  }
};
