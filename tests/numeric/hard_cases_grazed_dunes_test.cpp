// Issue 14: the depth map's false shadow on a caster's own lit side where the light grazes it.
// The seventh audit's grazing_10535 (grazed_dunes_two_boxes.json): two boxes on dunes that cast
// and receive, the light 0.4 m up. Its 256-texel map shadowed 23 pixels of the dunes' lee side
// 6 m off, which the light meets at under a degree and a texel's ray half a texel lower strikes
// the crest in front, 1.4 m nearer than the slope term (bounded to 6 texels) and the receiver's
// bias push apart; no shadow edge or foot is near, so no estimate saw it and the frame was
// served with 0.113% interior error. The estimate now replays the lookup on such grazed pixels
// (depth_map_self_shadow.h): the map must be right or refused by name, naming a size that is.
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

const std::string kGrazedDunesFile = "grazed_dunes_two_boxes.json";
const std::string kGrazedEdges = "the shadow texels would move its edges beyond their band";

// The frame as the audit found it, and with the dunes' amplitude 0.07 m (7 cm instead of 5),
// where the lee side's false shadow partly borders the dunes' own true shadow.
gs::Scene grazed_dunes(bool higher_dunes) {
  gs::Scene scene = load(kGrazedDunesFile);
  if (higher_dunes) {
    for (gs::SceneObject &object : scene.objects) {
      if (object.name != "dunes") continue;
      // y = amplitude sin(k x) cos(k z) (scene_file.cpp): heights scaled by 0.07 / 0.05.
      for (glm::vec3 &p : object.mesh.positions) p.y *= 1.4f;
    }
  }
  return scene;
}

// With the estimates off the map is measured over the budget on the audit's frame: the case can
// fail (23 px of 20393, 0.113%). With the dunes at 0.07 m it was 23 px of 20211 (0.114%) while
// the truth started its shadow rays off the surface along the normal; from the segment to the
// light it is 16 of 20178 (0.079%), so that frame no longer shows the check is needed, though the
// check still refuses it (below).
TEST(HardCases, DepthMapOnGrazedDunesWithTheCheckOffIsOverBudget) {
  const gs::Scene scene = grazed_dunes(false);
  const Truth truth = truth_of(scene);
  gs::TechniqueOptions options;
  options.depth_map_largest_footprint_px = INFINITY;
  const Outcome o = run("depth-map", scene, truth, options);
  report(kGrazedDunesFile + " depth-map check off", o);
  EXPECT_TRUE(o.refusals.empty());
  EXPECT_GT(o.errors.false_shadow_interior + o.errors.false_light_interior, kInteriorBudget);
}

// At 256 texels the map refuses the dunes by name and names 512, where it is served and right
// (measured 0.083% and 0.005% interior).
TEST(HardCases, DepthMapOnGrazedDunesIsRefusedNamingASizeThatIsRight) {
  for (const bool higher : {false, true}) {
    gs::Scene scene = grazed_dunes(higher);
    const std::string name = kGrazedDunesFile + (higher ? " higher dunes" : "");
    expect_these_right_or_refused(name, scene, {"depth-map"},
                                  {{"depth-map", "light 0 and 'dunes': " + kGrazedEdges}}, true);
    const Truth truth = truth_of(scene);
    const Outcome refused = run("depth-map", scene, truth);
    ASSERT_FALSE(refused.refusals.empty());
    EXPECT_NE(refused.refusals[0].find("(size 512 would be accepted)"), std::string::npos)
        << refused.refusals[0];
    scene.lights[0].shadow_size = 512;
    expect_these_right_or_refused(name + " at 512", scene, {"depth-map"}, {}, true);
  }
}

}  // namespace
