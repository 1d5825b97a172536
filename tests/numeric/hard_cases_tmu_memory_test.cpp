// More shadow textures than TMU0's 2 MB holds (issue 14): six casters with 512-texel maps (four
// 256-texel tiles each) under one light, and nine with 256-texel maps under two lights, in
// tests/hard_cases (many_casters_*.json). A 256x256 ARGB_4444 texture takes 128 KB, so 16 fit.
// Step 2 places the first 16; the others are loaded just before step 5 (and the mask pass)
// draws with them, over textures already drawn with (shadow_texture_memory.h): the LFB path
// downloads its read-back again, the direct path draws step 1 again into TMU memory. Before,
// the casters past the 16th were refused ("TMU memory is full"), 0.2 to 0.4% interior false
// light with the error.
#include "hard_case_checks.h"

#include "techniques/projected/projected_shadow.h"

#include <gtest/gtest.h>

#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

struct ManyCasters {
  const char *file;
  bool one_light;  // shadow_where_unlit asks light 0 alone
};
const ManyCasters kManyCasters[] = {{"many_casters_512.json", true},
                                    {"many_casters_two_lights.json", false}};

gs::TechniqueOptions direct_path() {
  gs::TechniqueOptions options;
  options.projected.direct_path = true;
  return options;
}

// The projected frame of `scene` in a Glide window of its size: how many textures, whether
// step 5 had to load some, and which paths step 1 took.
struct Textures {
  std::size_t jobs = 0;
  bool loaded = false;
  std::size_t direct = 0;  // textures step 1 drew straight into TMU memory
  std::vector<std::string> errors;
};

Textures textures_of(const gs::Scene &scene, const gs::ProjectedShadowOptions &options) {
  grGlideInit();
  EXPECT_TRUE(glideShimSetWindowSize(scene.width, scene.height));
  EXPECT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1))
      << glideShimGetLastErrorMessage();
  const gs::ShadowFrame frame = gs::render_projected_shadows(scene, options, false);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
  grGlideShutdown();
  Textures t;
  t.jobs = frame.jobs.size();
  t.loaded = frame.textures_loaded;
  for (const gs::ShadowJob &job : frame.jobs) t.direct += job.view.direct_path;
  t.errors = frame.errors;
  return t;
}

// The scenes need more than the 16 textures TMU0 holds, on either path, and every one is cast.
TEST(HardCases, ManyCastersNeedMoreTexturesThanTmuMemoryHolds) {
  for (const ManyCasters &c : kManyCasters) {
    const gs::Scene scene = load(c.file);
    gs::ProjectedShadowOptions lfb, direct;
    direct.direct_path = true;
    const Textures on_lfb = textures_of(scene, lfb);
    const Textures on_direct = textures_of(scene, direct);
    EXPECT_GT(on_lfb.jobs, 16u) << c.file;
    EXPECT_TRUE(on_lfb.loaded) << c.file;
    EXPECT_EQ(on_lfb.direct, 0u) << c.file << ": every texture should take the LFB path";
    EXPECT_EQ(on_direct.jobs, on_lfb.jobs) << c.file;
    EXPECT_TRUE(on_direct.loaded) << c.file;
    EXPECT_EQ(on_direct.direct, on_direct.jobs) << c.file;
    for (const std::string &e : on_lfb.errors) ADD_FAILURE() << c.file << " LFB: " << e;
    for (const std::string &e : on_direct.errors) ADD_FAILURE() << c.file << " direct: " << e;
  }
}

// Every technique at its defaults (the projected ones on the LFB path) within 0.1%.
TEST(HardCases, ManyCastersRightOnTheLfbPath) {
  for (const ManyCasters &c : kManyCasters) expect_right_or_refused(c.file, {}, c.one_light);
}

// The projected ones with step 1 drawing straight into TMU memory, within 0.1%.
TEST(HardCases, ManyCastersRightOnTheDirectPath) {
  for (const ManyCasters &c : kManyCasters) {
    const gs::Scene scene = load(c.file);
    const Truth truth = truth_of(scene);
    ASSERT_GT(truth.shadow_pixels, 200) << c.file << ": no shadow, the case tests nothing";
    for (const std::string name : {"projected", "projected-chroma"}) {
      const Outcome o = run(name, scene, truth, direct_path());
      report(std::string(c.file) + " " + name + " direct", o);
      expect_clean_glide(name, o);
      for (const std::string &e : o.refusals) ADD_FAILURE() << c.file << " " << name << ": " << e;
      EXPECT_LE(o.errors.false_shadow_interior + o.errors.false_light_interior, kInteriorBudget)
          << c.file << " " << name << " direct";
      if (c.one_light) {
        EXPECT_LE(shadow_where_unlit(o, truth, scene.width, scene.height).farthest, 1)
            << c.file << " " << name << ": shadow where the light does not shine";
      }
    }
  }
}

}  // namespace
