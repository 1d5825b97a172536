// Receivers with more than one layer as the light sees them, and receivers in front of part of a
// caster (tests/hard_cases/README.md, "receiver layers"): a post behind a ridge of its own floor
// (the floor casting or not), a pole reaching over that ridge (two textures for the projected
// techniques, one per layer; refused by them where the floor casts), a stick beside a drum that hides its lower
// part from the light, receivers in front of a caster's inside (a cube over a plate). Each is
// checked by expect_right_or_refused (hard_case_checks.h), also with the light turned about its
// target.
#include "hard_case_checks.h"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// `scene` with its light turned `degrees` about the vertical through its target (world space).
gs::Scene light_turned_about_target(gs::Scene scene, float degrees) {
  gs::SpotLight &light = scene.lights[0];
  const glm::mat4 about_target =
      glm::translate(glm::mat4(1.0f), light.target) *
      glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0, 1, 0)) *
      glm::translate(glm::mat4(1.0f), -light.target);
  light.position = glm::vec3(about_target * glm::vec4(light.position, 1.0f));
  return scene;
}

// `file` as it is and with its light turned `degrees` either way.
void expect_layers_case(const std::string &file, float degrees,
                        const std::map<std::string, std::string> &refusals = {}) {
  expect_right_or_refused(file, refusals);
  for (const float turn : {-degrees, degrees}) {
    expect_right_or_refused(file + " turned " + std::to_string(turn),
                            light_turned_about_target(hard_cases::load(file), turn), refusals);
  }
}

}  // namespace

// The ridge is nearer the light than the whole post: it never takes the post's shadow, so it
// does not mask the post's texture, and the floor behind the post is shadowed (before: the
// post was cut at the ridge and the floor behind it lost the whole shadow, 0.83% interior
// false light; with the floor casting, 7.0% of the pixels the comparison counts).
TEST(HardCases, PostBehindARidgeOfItsFloor) {
  expect_layers_case("post_behind_ridge.json", 20.0f);
  gs::Scene casting = hard_cases::load("post_behind_ridge.json");
  casting.objects[0].casts_shadow = true;
  expect_right_or_refused("post_behind_ridge.json with the floor casting", casting,
                          {{"stencil-volume", "'ridge and floor' is not a closed mesh"}});
}

// Before: 0.33% interior false light reported as success (4.4% with the floor casting), then
// refused by the projected techniques. The floor casts nothing: its ridge takes the texture
// masked by its nearest surface (the pole's top), the floor the ridge hides from the light the
// one masked by its farthest (the top and the middle), and every technique is right. With the
// floor casting, the projected techniques still refuse by name (0.111% served with both textures).
TEST(HardCases, PoleOverARidgeIsRightWhereTheFloorCastsNothing) {
  expect_layers_case("pole_over_ridge.json", 15.0f);
  gs::Scene casting = hard_cases::load("pole_over_ridge.json");
  casting.objects[0].casts_shadow = true;
  const std::vector<std::string> projected = {"projected", "projected-chroma"};
  const std::map<std::string, std::string> refusals = {
      {"projected", "lies between two parts of 'ridge and floor'"},
      {"projected-chroma", "lies between two parts of 'ridge and floor'"}};
  expect_these_right_or_refused("pole_over_ridge.json with the floor casting", casting, projected,
                                refusals, true);
}

// Before: 0.18% interior false shadow on the drum's cap (0.79% without the floor).
TEST(HardCases, StickBesideADrumThatHidesItsFoot) {
  expect_layers_case("stick_beside_drum.json", 25.0f);
}

// Receivers lying wholly inside a caster's outline as the light sees it, nearer the light: they
// cross none of the caster's edge samples, so receiver_layers does not mask them; step 3 leaves
// them unshaded (below). Before: the cube over the plate took the plate's shadow (0.376%
// interior false shadow, reported as success; the third audit's classes_3045, 0.234%).
// The ball on the slab and the fighter on the stage were right already; they are the same class
// with the receiver touching the caster.
// Receivers standing on the caster with faces nearly edge-on to the light: the masked texture cut
// them out of the caster's shadow only to the texel, which spans many pixels on such a face; step
// 3 now leaves unshaded every receiver triangle wholly nearer the light than the caster's surface
// behind it (caster_surface_from_light.h). Before, reported as success: posts_on_table turned -20
// degrees 0.240% (chroma 0.248%), pillars_on_plinth turned 10 degrees 0.175% (0.178%),
// book_on_crate turned -15 degrees 0.110% (0.117%) interior false shadow.
TEST(HardCases, ReceiversInFrontOfACastersInside) {
  expect_layers_case("cube_over_tilted_plate.json", 20.0f);
  expect_layers_case("ball_on_raised_slab.json", 25.0f);
  expect_layers_case("fighter_on_stage.json", 25.0f);
  expect_layers_case("posts_on_table.json", 20.0f);
  expect_layers_case("pillars_on_plinth.json", 10.0f);
  expect_layers_case("book_on_crate.json", 15.0f);
}
