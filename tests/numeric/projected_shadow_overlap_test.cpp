// Step 5 with several shadows of one light overlapping: each pixel darkened once, and with
// filtered edges no lighter seam where one shadow's edge lies inside another's core.
#include "techniques/projected/projected_shadow.h"

#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include "projected_shadow_fixture.h"

#include <vector>

namespace {

// Issue 16 item 4: two casters of one light whose shadows overlap darken the overlap once, as
// a single shadow does: each pixel step 5 darkens is marked in the depth buffer, and the next
// shadow of the same light fails there.
TEST_F(ProjectedShadowTest, OverlappingShadowsOfOneLightDarkenOnce) {
  gs::Scene scene = box_over_floor();
  scene.lights[0].position = {0, 8, 0};
  scene.objects[1] = object("left", gs::make_box({0.6f, 0.1f, 0.3f}), {-0.3f, 2.0f, 0});
  scene.objects.push_back(object("right", gs::make_box({0.6f, 0.1f, 0.3f}), {0.3f, 2.5f, 0.1f}));
  gs::ProjectedShadowOptions options;
  options.bilinear = false;  // hard edges: every shadowed pixel is darkened by the full alpha
  gs::ShadowFrame frame;
  const std::vector<bool> mask = shadow_mask(scene, options, &frame);
  ASSERT_EQ(frame.jobs.size(), 2u);
  gs::render_projected_shadows(scene, options, false);
  const std::vector<FxU16> both = back_buffer();
  // Each caster alone: where both shadows fall, the frame is what either one alone gives.
  std::vector<std::vector<FxU16>> alone;
  std::vector<std::vector<bool>> alone_mask;
  for (std::size_t caster : {1u, 2u}) {
    gs::Scene one = scene;
    one.objects[caster == 1 ? 2 : 1].casts_shadow = false;
    alone_mask.push_back(shadow_mask(one, options));
    gs::render_projected_shadows(one, options, false);
    alone.push_back(back_buffer());
  }
  const std::vector<bool> floor = coverage(scene, 0);
  int overlap = 0, darker = 0;
  for (std::size_t i = 0; i < both.size(); ++i) {
    if (!floor[i] || !alone_mask[0][i] || !alone_mask[1][i]) continue;
    ++overlap;
    if (both[i] != alone[0][i]) ++darker;
  }
  EXPECT_GT(overlap, 100) << "the shadows do not overlap: the test tests nothing";
  EXPECT_EQ(darker, 0) << "the overlap is darkened twice";
  // And the mask is the union of the two.
  int union_mismatch = 0;
  for (std::size_t i = 0; i < mask.size(); ++i)
    union_mismatch += mask[i] != (alone_mask[0][i] || alone_mask[1][i]);
  EXPECT_EQ(union_mismatch, 0);
}

// The same with filtered edges, the default: where one shadow's soft edge lies inside the
// other's core, the pixel is darkened by the core, as it would be by that shadow alone; the
// soft edge drawn first must not mark it lighter (a bright seam inside the shadow). A shadow's
// core is where its filtered frame equals its point-sampled one (full texture alpha).
TEST_F(ProjectedShadowTest, OverlappingFilteredShadowsLeaveNoSeamInEachOthersCore) {
  gs::Scene scene = box_over_floor();
  scene.lights[0].position = {0, 8, 0};
  scene.objects[1] = object("left", gs::make_box({0.6f, 0.1f, 0.3f}), {-0.3f, 2.0f, 0});
  scene.objects.push_back(object("right", gs::make_box({0.6f, 0.1f, 0.3f}), {0.3f, 2.5f, 0.1f}));
  gs::ProjectedShadowOptions filtered, point;
  point.bilinear = false;
  ASSERT_EQ(gs::render_projected_shadows(scene, filtered, false).jobs.size(), 2u);
  const std::vector<FxU16> both = back_buffer();
  const std::vector<bool> floor = coverage(scene, 0);
  for (std::size_t caster : {1u, 2u}) {
    gs::Scene one = scene;
    one.objects[caster == 1 ? 2 : 1].casts_shadow = false;
    const std::vector<bool> hard = shadow_mask(one, point);
    gs::render_projected_shadows(one, point, false);
    const std::vector<FxU16> alone_point = back_buffer();
    gs::render_projected_shadows(one, filtered, false);
    const std::vector<FxU16> alone = back_buffer();
    int core = 0, differ = 0;
    for (std::size_t i = 0; i < both.size(); ++i) {
      if (!floor[i] || !hard[i] || alone[i] != alone_point[i]) continue;
      ++core;
      differ += both[i] != alone[i];
    }
    EXPECT_GT(core, 300) << "caster " << caster << " has no core: the test tests nothing";
    EXPECT_EQ(differ, 0) << "pixels of caster " << caster << "'s core that the other shadow's edge left lighter";
  }
}

}  // namespace
