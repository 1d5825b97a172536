// Scenes the project had not seen, by class (tests/hard_cases/README.md lists them): casters
// larger than a bounding-sphere view, casters longer than the beam is wide, the scene flags, and
// acne at the defaults, casters through their receivers. Each is checked by expect_right_or_refused (hard_case_checks.h): every
// technique within the interior-error budget against the ray-cast truth, or refused by name.
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

// A caster larger than the view a bounding sphere allows, the light behind or beside it: the
// projected techniques fit their view to what the cone holds of it; one that surrounds the
// light is refused by name (projected) or as an open mesh (stencil volumes).
TEST(HardCases, WideCasterBehindTheLight) { expect_right_or_refused("wall_behind_light.json"); }
TEST(HardCases, LongCasterBesideTheLight) { expect_right_or_refused("bar_beside_light.json"); }
TEST(HardCases, CasterSurroundingTheLightIsRefusedByName) {
  expect_right_or_refused("light_inside_tube.json",
                          {{"projected", "light 0 and 'tube': no single projection"},
                           {"projected-chroma", "light 0 and 'tube': no single projection"},
                           {"stencil-volume", "'tube' is not a closed mesh"}});
}

// Casters longer than the beam is wide: their shadows stop at the beam's edge, per pixel, for
// a round cone, a square beam map, and a cone whose rim crosses coarse floor triangles.
TEST(HardCases, ShadowStopsAtTheNarrowConesEdge) {
  expect_right_or_refused("bar_across_narrow_cone.json");
}
TEST(HardCases, ShadowStopsAtTheSquareBeamsSides) {
  expect_right_or_refused("plank_square_beam.json");
}
TEST(HardCases, ShadowStopsAtTheConeInsideCoarseTriangles) {
  expect_right_or_refused("two_rods_wide_cone.json");
}
TEST(HardCases, ShadowStopsAtTheGobosBars) { expect_right_or_refused("gobo_bars.json"); }
// Floor triangles whose corners are all lit, each in another pane of the gobo: the bar between
// them is not (before, 1.2% and 0.35% false shadow there from the planar and projected ones).
TEST(HardCases, ShadowStopsAtTheGobosBarsInsideTrianglesAcrossThem) {
  expect_right_or_refused("gobo_wide_coarse_floor.json");
  expect_right_or_refused("gobo_oblique_ball_and_rod.json");
}

// casts_shadow and receives_shadow, as the truth and every technique honour them.
TEST(HardCases, SceneFlagsAreHonouredByTruthAndTechniques) {
  expect_right_or_refused("flags_sign_and_ball.json");
  const gs::Scene scene = hard_cases::load("flags_sign_and_ball.json");
  const Truth truth = truth_of(scene);
  long ball = 0, ball_shadowed = 0;
  for (std::size_t i = 0; i < truth.exact.object.size(); ++i) {
    if (truth.exact.object[i] != 4) continue;
    ++ball;
    ball_shadowed += truth.exact.shadow[i] + truth.exact.self_shadow[i];
  }
  EXPECT_GT(ball, 200);
  EXPECT_EQ(ball_shadowed, 0) << "the ball receives no shadow";
  for (const std::string &name : kTechniques) {
    const Outcome o = run(name, scene, truth);
    long darkened = 0;
    for (std::size_t i = 0; i < o.mask.size(); ++i) darkened += o.mask[i] && truth.exact.object[i] == 4;
    EXPECT_EQ(darkened, 0) << name << ": the ball is darkened";
  }
}

// Acne at the defaults: a plate tilted towards an oblique light, and casters whose lit sides
// the camera sees edge-on to a light that faces it.
TEST(HardCases, NoAcneOnATiltedPlateAtTheDefaults) {
  expect_right_or_refused("tilted_plate_oblique.json");
}
TEST(HardCases, NoAcneAlongLitSilhouettesAtTheDefaults) {
  expect_right_or_refused("light_facing_camera_posts.json");
}

// A caster through its receiver: the part beyond a planar receiver casts nothing on it. The
// projected techniques give the pair a texture of the caster clipped to the receiver's plane
// (pierced_receivers.h); the others follow the geometry.
TEST(HardCases, CasterThroughTheFloorCastsOnlyItsPartAbove) {
  expect_right_or_refused("post_through_floor.json");
  expect_right_or_refused("ball_sunk_in_floor.json");
}
TEST(HardCases, CasterThroughAWallOrARamp) {
  expect_right_or_refused("plank_through_wall.json");
  expect_right_or_refused("crate_through_ramp.json");
}
// The project's own sample of it: the tetrahedron of scenes/obj_mesh.json reaches 0.5 m below
// its floor (0.24 to 0.47% interior error for the projected techniques before the clip).
TEST(HardCases, ObjMeshSampleTetrahedronThroughTheFloor) {
  expect_right_or_refused("../../scenes/obj_mesh.json");
}
