// Issue 14's random audit, class wall_behind_light (tools/random_scenes.py --classes, seed 4110):
// a long wall with a wide spotlight 0.2 m above its top; the wall's far end lies behind the
// light's plane. The depth map marked a dotted line of false shadow along the wall's top, lit at
// a grazing angle (0.538% of the receiver pixels, reported as success): the receiver-plane bias
// (depth_map_lookup.h) was left off every triangle with a corner behind the light's plane (q <=
// 0), so the top's two long triangles compared their own texels unbiased, and the slope term's
// push, bounded to 6 texels' widths, is less than such a face's depth change across one texel.
// The bias now comes from the homogeneous corners. Scenes tests/hard_cases/audit/da1 to da5
// (their README): walls, a ledge, a slab and a block with the light just above their tops,
// maps of 256 and 512 texels, screens of 160x120 to 320x240; every technique right or
// refused by name.
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

const char *const kGrazingTops[] = {
    "audit/da1_wall_top_light_15cm_map256.json", "audit/da2_ledge_light_beside_map512.json",
    "audit/da3_slab_light_over_top_map256.json", "audit/da4_block_light_at_corner_map512.json",
    "audit/da5_wall_turned_light_30cm_low_camera.json"};

// da1's 256 texels are too coarse for the point-sampled chroma-key variant (3.2 px on the floor,
// its limit 3.0): refused by name, as its footprint check does.
TEST(HardCases, TopsLitAtAGrazingAngleReachingBehindTheLight) {
  for (const char *file : kGrazingTops) {
    const std::string name = file;
    if (name.find("da1_") != std::string::npos) {
      const std::map<std::string, std::string> coarse = {
          {"projected-chroma", "light 0 and 'wall': a shadow texel spans"}};
      expect_right_or_refused(name, coarse);
    } else {
      expect_right_or_refused(name);
    }
  }
}

// The check sees the fault: without the receiver's bias the depth map's acne on da1's and da2's
// tops is back (measured 0.46% and 1.7%; 0.33% and 1.2% before the fix, when only those triangles got none).
// Drawn and measured with the estimates off: with them on, the replay of grazed pixels
// (depth_map_self_shadow.h) refuses da2's ledge (about 148 px estimated, 16 accepted).
TEST(HardCases, TopsLitAtAGrazingAngleWithoutTheReceiverBiasHaveAcne) {
  gs::TechniqueOptions no_receiver_bias;
  no_receiver_bias.depth_bias_receiver = 0.0f;
  no_receiver_bias.depth_map_largest_footprint_px = INFINITY;
  for (const char *file : {"audit/da1_wall_top_light_15cm_map256.json",
                           "audit/da2_ledge_light_beside_map512.json"}) {
    const gs::Scene scene = load(file);
    const Truth truth = truth_of(scene);
    const Outcome o = run("depth-map", scene, truth, no_receiver_bias);
    report(std::string(file) + " depth-map without the receiver bias", o);
    EXPECT_GT(o.errors.false_shadow_interior, kInteriorBudget) << file;
  }
}

}  // namespace
