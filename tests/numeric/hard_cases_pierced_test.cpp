// Casters through receivers that are not planar (tests/hard_cases/README.md, "caster through a
// curved or faceted receiver"): a crate in a faceted mound, a limb in a drum and in the demo's
// ring, a rod through a roof ridge, a post in a wavy heightfield, a ball pressed into a crease;
// each also with the light turned about the scene and at other map sizes. Each is checked by
// expect_right_or_refused (hard_case_checks.h): every technique within the interior-error budget
// against the ray-cast truth, or refused by name.
#include "hard_case_checks.h"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// `file` as it is, then with its light turned `degrees` either way about the vertical through
// its target (world space), then at map sizes 128 and 512.
void expect_right_or_refused_around(const std::string &file, float degrees) {
  expect_right_or_refused(file);
  for (const float turn : {-degrees, degrees}) {
    gs::Scene scene = hard_cases::load(file);
    gs::SpotLight &light = scene.lights[0];
    const glm::mat4 about_target =
        glm::translate(glm::mat4(1.0f), light.target) *
        glm::rotate(glm::mat4(1.0f), glm::radians(turn), glm::vec3(0, 1, 0)) *
        glm::translate(glm::mat4(1.0f), -light.target);
    light.position = glm::vec3(about_target * glm::vec4(light.position, 1.0f));
    expect_right_or_refused(file + " turned " + std::to_string(turn), scene);
  }
  for (const int size : {128, 512}) {
    gs::Scene scene = hard_cases::load(file);
    scene.lights[0].shadow_size = size;
    expect_right_or_refused(file + " at " + std::to_string(size), scene);
  }
}

}  // namespace

TEST(HardCases, CrateSunkInAFacetedMound) {
  expect_right_or_refused_around("box_sunk_in_mound.json", 40.0f);
}
TEST(HardCases, LimbPushedIntoADrum) {
  expect_right_or_refused_around("limb_in_drum.json", 35.0f);
}
TEST(HardCases, RodThroughARoofRidge) {
  expect_right_or_refused_around("rod_through_ridge.json", 30.0f);
}
TEST(HardCases, PostSunkInWavyGround) {
  expect_right_or_refused_around("post_in_waves.json", 45.0f);
}
TEST(HardCases, BallPressedIntoACrease) {
  expect_right_or_refused_around("ball_in_crease.json", 30.0f);
}
TEST(HardCases, LimbSunkInTheRingsMat) {
  expect_right_or_refused_around("limb_in_ring.json", 15.0f);
}
// Every corner of the rod is behind the valley's surface, but its middle is above the crease.
TEST(HardCases, RodSunkAtBothEndsAcrossAValley) {
  expect_right_or_refused_around("rod_across_valley.json", 30.0f);
}
