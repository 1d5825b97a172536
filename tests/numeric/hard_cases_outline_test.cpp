// Issue 14's last silent failures (the random audit's random_1004 and random_1041): a receiver in
// front of its caster as the light sees them (a box over or sunk into the ring's mat, a heightfield
// or a tilted plane, all of which cast), so the projected techniques give the receiver a texture
// masked by its surface (pierced_surfaces.cpp). Beyond the receiver's outline from the light that
// texture held the caster behind it, and the receiver's own points next to the outline read it
// through the filter: specks of false shadow along the outline (random_1004 0.157%, the
// chroma-key variant 0.174%; outline_slab_over_tilted_plane 0.129% and 0.145%), reported as
// success. The outline's fins keep the caster there out of the texture. Each scene is checked by
// expect_right_or_refused (hard_case_checks.h): every technique within the interior-error budget
// against the ray-cast truth, or refused by name.
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

std::map<std::string, std::string> open_caster(const std::string &caster) {
  return {{"stencil-volume", "'" + caster + "' is not a closed mesh"}};
}

std::map<std::string, std::string> open_caster_coarse_map(const std::string &caster) {
  std::map<std::string, std::string> refusals = open_caster(caster);
  refusals["depth-map"] = "light 0 and '" + caster + "': a shadow texel spans";
  return refusals;
}

}  // namespace

TEST(HardCases, ReceiverOutlineOverTheRing) {
  expect_right_or_refused("outline_box_over_ring.json", open_caster_coarse_map("ring"));
  expect_right_or_refused("outline_box_sunk_in_ring.json", open_caster("ring"));
}

TEST(HardCases, ReceiverOutlineOverAHeightfield) {
  expect_right_or_refused("outline_ball_over_waves.json", open_caster_coarse_map("ground"));
  expect_right_or_refused("outline_crate_sunk_in_waves.json", open_caster("ground"));
}

TEST(HardCases, ReceiverOutlineOverATiltedPlane) {
  expect_right_or_refused("outline_slab_over_tilted_plane.json", open_caster_coarse_map("ramp"));
  expect_right_or_refused("outline_box_sunk_in_tilted_plane.json", open_caster("ramp"));
}
