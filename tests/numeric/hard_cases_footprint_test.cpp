// Issue 14's class "shadow texture too coarse for the screen": scenes of tests/hard_cases (the
// footprint class of its README) and the fight, the projected techniques at every map size from
// 32 to 256. Each run either refuses by name (a texel spans more screen pixels than
// kLargestTexelFootprintPx where the shadow falls: texel_footprint.h) or stays within the
// interior-error budget against the ray-cast truth.
#include "hard_case_checks.h"

#include "scene/fight_scene.h"
#include "techniques/texel_error/texel_footprint.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

struct Refused {
  std::set<int> projected, chroma;  // the sizes each refused
};

// Runs both projected techniques on `scene` at each size and says which sizes each refused;
// every other size must be within the budget. The chroma-key variant samples one texel, so its
// limit is lower (texel_footprint.h): it refuses at least what the bilinear one refuses.
Refused expect_fine_or_refused(const std::string &file, const gs::Scene &scene,
                               const std::vector<int> &sizes) {
  const Truth truth = truth_of(scene);
  EXPECT_GT(truth.shadow_pixels, 200) << file << ": no shadow, the case tests nothing";
  Refused result;
  for (int size : sizes) {
    for (const std::string name : {"projected", "projected-chroma"}) {
      std::set<int> &refused = name == "projected" ? result.projected : result.chroma;
      gs::TechniqueOptions options;
      options.projected.size = size;
      const Outcome o = run(name, scene, truth, options);
      report(file + " " + name + " size " + std::to_string(size), o);
      expect_clean_glide(name, o);
      if (!o.refusals.empty()) {
        refused.insert(size);
        for (const std::string &e : o.refusals) {
          EXPECT_NE(e.find("-texel shadow is too coarse for the screen"), std::string::npos) << e;
          EXPECT_NE(e.find("screen pixels (the largest accepted is"), std::string::npos) << e;
        }
        continue;
      }
      EXPECT_EQ(result.projected.count(size), 0u) << file << " size " << size << ": " << name
                                                  << " accepted what projected refused";
      EXPECT_LE(o.errors.false_shadow_interior + o.errors.false_light_interior, kInteriorBudget)
          << file << " " << name << " size " << size;
    }
  }
  return result;
}

const std::vector<int> kSizes = {32, 64, 128, 256};

}  // namespace

// Where coarse maps were measured wrong (docs/hard_cases_results.md, "Shadow texels against screen
// pixels"), they must be refused; the finer sizes must be accepted.
TEST(HardCases, CoarseTexelsTowardsTheCameraAreRefused) {
  const Refused crate =
      expect_fine_or_refused("crate_toward_camera.json", load("crate_toward_camera.json"), kSizes);
  EXPECT_EQ(crate.projected, std::set<int>({32}));
  EXPECT_EQ(crate.chroma, std::set<int>({32}));
  const Refused rail =
      expect_fine_or_refused("rail_toward_camera.json", load("rail_toward_camera.json"), kSizes);
  // 128 since the estimate of the error along the shadow's edges (shadow_edge_error.h): 0.086%
  // measured there, the estimate 0.14% of the receivers' pixels (docs/hard_cases_results.md).
  EXPECT_EQ(rail.projected, std::set<int>({32, 64, 128}));
  EXPECT_EQ(rail.chroma, std::set<int>({32, 64, 128}));
}

// Scenes whose every size is right or refused; the sizes their files ask for are accepted.
TEST(HardCases, CoarseTexelsRightOrRefused) {
  for (const char *file : {"crate_close_camera.json", "pole_low_sun.json", "table_high_light.json",
                           "sign_on_wall.json", "bar_low_light.json"}) {
    const gs::Scene scene = load(file);
    const Refused refused = expect_fine_or_refused(file, scene, kSizes);
    EXPECT_EQ(refused.chroma.count(scene.lights[0].shadow_size), 0u) << file;
    EXPECT_EQ(refused.chroma.count(128), 0u) << file;
  }
}

// The same table seen from close by (the camera 2.5 m from the table's edge, 320x240): the
// footprint grows as the camera nears, and the sizes refused grow with it.
TEST(HardCases, CoarseTexelsNearTheCamera) {
  gs::Scene scene = load("table_high_light.json");
  scene.width = 320, scene.height = 240;
  scene.camera.position = glm::vec3(1.0f, 1.6f, 3.0f);
  scene.camera.target = glm::vec3(0.0f, 0.0f, 0.0f);
  const Refused refused = expect_fine_or_refused("table_high_light.json (close)", scene, kSizes);
  EXPECT_EQ(refused.projected, std::set<int>({32, 64, 128}));
  EXPECT_EQ(refused.chroma.count(256), 0u);
}

// The fight at the bench's 640x480: 64 texels were measured 0.10 to 0.37% interior error
// (refused), 128 within 0.05% (accepted by the bilinear technique; the chroma-key variant's
// lower limit refuses it, docs/hard_cases_results.md), 256 by both.
TEST(HardCases, FightRefusesCoarseMapsOnly) {
  gs::FightScene fight(640, 480, 256);
  const Refused refused = expect_fine_or_refused("fight t=2.1", fight.at(2.1f), {64, 128, 256});
  EXPECT_EQ(refused.projected, std::set<int>({64}));
  EXPECT_EQ(refused.chroma, std::set<int>({64, 128}));
}
