// Issue 14's y1 and y2 (tests/hard_cases/audit): the projected techniques on a crate and a rail
// whose shadows run towards the camera, the light moved; and wide_cone_hall, whose walls' shadow
// edges lie under their feet. The texel-footprint measure (src/techniques/texel_error/texel_footprint.*)
// takes a texel's width across its stretch, which moves an edge running along the light's
// direction; the shadows' far ends (the crate's top, the rail's bar) run across it, where a
// texel's long side moves them, and a hidden edge excuses no strayed pixel. Both are caught by
// the estimate of the error along each silhouette edge's shadow (src/techniques/
// shadow_edge_error.*): before it, bilinear accepted y1 at 0.68% interior error, y2 at 0.57%
// and wide_cone_hall at 0.157% (docs/hard_cases_results.md). The depth map measures its texels
// the same way (src/techniques/depth_map/depth_map_footprint.*, with its own lookups): before, it accepted
// y1 at 0.339% interior error.
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// One run right (within the interior budget) or refused as too coarse for the screen.
void expect_right_or_coarse(const std::string &what, const Outcome &o) {
  expect_clean_glide(what, o);
  if (!o.refusals.empty()) {
    EXPECT_NE(o.refusals[0].find("too coarse for the screen"), std::string::npos) << o.refusals[0];
    return;
  }
  EXPECT_LE(o.errors.false_shadow_interior + o.errors.false_light_interior, kInteriorBudget)
      << what;
}

// Both projected techniques right (within the interior budget) or refused as too coarse.
void expect_projected_right_or_coarse(const std::string &what, const gs::Scene &scene) {
  const Truth truth = truth_of(scene);
  ASSERT_GT(truth.shadow_pixels, 200) << what << ": no shadow, the case tests nothing";
  for (const std::string name : {"projected", "projected-chroma"}) {
    const Outcome o = run(name, scene, truth);
    report(what + " " + name, o);
    expect_right_or_coarse(what + " " + name, o);
  }
}

// The depth map, with the percentage-closer lookup and the nearest one, right or refused as too
// coarse.
void expect_depth_map_right_or_coarse(const std::string &what, const gs::Scene &scene) {
  const Truth truth = truth_of(scene);
  ASSERT_GT(truth.shadow_pixels, 200) << what << ": no shadow, the case tests nothing";
  for (bool linear : {true, false}) {
    gs::TechniqueOptions options;
    options.depth_map_linear = linear;
    const std::string name = linear ? "depth-map" : "depth-map nearest";
    const Outcome o = run("depth-map", scene, truth, options);
    report(what + " " + name, o);
    expect_right_or_coarse(what + " " + name, o);
  }
}

}  // namespace

TEST(HardCases, ShadowEndsAcrossTheTexelStretchAreRightOrRefused) {
  expect_projected_right_or_coarse("y1", load("audit/y1_crate_toward_camera_light_moved.json"));
  expect_projected_right_or_coarse("y2", load("audit/y2_rail_toward_camera_light_moved.json"));
  // y1 with the light higher and further aside (world metres): the crate's shadow shorter, its
  // far end seen nearer the crate.
  gs::Scene crate = load("audit/y1_crate_toward_camera_light_moved.json");
  crate.lights[0].position = glm::vec3(-0.9f, 1.8f, -8.548f);
  expect_projected_right_or_coarse("y1, the light at (-0.9, 1.8)", crate);
  // y2 with the light 0.5 m to the side and 0.2 m lower.
  gs::Scene rail = load("audit/y2_rail_toward_camera_light_moved.json");
  rail.lights[0].position += glm::vec3(0.5f, -0.2f, 0.0f);
  expect_projected_right_or_coarse("y2, the light moved (0.5, -0.2, 0)", rail);
}

TEST(HardCases, ShadowEdgesUnderTheCastersFeetAreRightOrRefused) {
  expect_projected_right_or_coarse("wide_cone_hall", load("wide_cone_hall.json"));
  // The light 0.4 m towards the left wall and 0.3 m lower (world metres): the right wall's
  // inner face lit more squarely, the left's more obliquely.
  gs::Scene hall = load("wide_cone_hall.json");
  hall.lights[0].position += glm::vec3(-0.4f, -0.3f, 0.0f);
  expect_projected_right_or_coarse("wide_cone_hall, the light moved (-0.4, -0.3, 0)", hall);
}

// The depth map on y1 and y2 and on variations of y1 (tests/hard_cases/audit, l1 to l3): the
// crate turned 45 degrees (0.134% of the screen interior error before the estimate along the
// edges, accepted), the light higher, maps of 128.
TEST(HardCases, DepthMapShadowEndsAcrossTheTexelStretchAreRightOrRefused) {
  expect_depth_map_right_or_coarse("y1", load("audit/y1_crate_toward_camera_light_moved.json"));
  expect_depth_map_right_or_coarse("y2", load("audit/y2_rail_toward_camera_light_moved.json"));
  expect_depth_map_right_or_coarse("l1", load("audit/l1_crate_turned_toward_camera_map64.json"));
  expect_depth_map_right_or_coarse("l2", load("audit/l2_crate_toward_camera_light_higher_map64.json"));
  expect_depth_map_right_or_coarse("l3", load("audit/l3_crate_toward_camera_map128.json"));
}
