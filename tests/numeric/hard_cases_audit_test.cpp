// The second audit's findings (tests/hard_cases/audit/README.md, "Second audit"), checked against
// the ray-cast truth with expect_right_or_refused (hard_case_checks.h). A closed caster around
// the light: its light-facing triangles are none of its shadow (every ray leaves it through a face
// turned away), so planar cast nothing (85% of the pixels wrong) and the projected techniques too
// (8.4%), both reported as success. A caster buried whole in a receiver with a layer behind it.
// Planar on y3 and y4 of the varied scenes (docs/hard_cases_log.md): covers next to the near
// plane and over receivers the shim clips to the screen. The depth map's bounded slope term
// where faces seen edge-on near a wide light were pushed past the floor (k1 and y6 moved).
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

const std::map<std::string, std::string> kCageRefusals = {
    {"projected", "light 0 and 'cage': no single projection"},
    {"projected-chroma", "light 0 and 'cage': no single projection"}};

// The light at two more places inside the box (world metres from the file's).
gs::Scene cage_with_light_moved(const glm::vec3 &offset) {
  gs::Scene scene = load("audit/k1_light_in_closed_box.json");
  scene.lights[0].position += offset;
  return scene;
}
const glm::vec3 kCageOffsets[] = {glm::vec3(0.4f, 0.3f, -0.3f), glm::vec3(-0.5f, -0.35f, 0.2f)};

// A 170-degree cone inside a closed box over the floor: everything outside the box is dark.
// Planar casts the box's back faces; the projected techniques refuse the 171-degree view.
TEST(HardCases, ClosedBoxAroundTheLightDarkensEverythingOutside) {
  expect_right_or_refused("audit/k1_light_in_closed_box.json", kCageRefusals);
  for (const glm::vec3 &offset : kCageOffsets) {
    expect_these_right_or_refused("k1, the light moved inside the box", cage_with_light_moved(offset),
                                  {"projected", "projected-chroma", "planar", "stencil-volume"},
                                  kCageRefusals, true);
  }
}

// The depth map on the same two places and two more, and with the box receiving shadow: 1.2%,
// 10.1%, 1.15% and 1.69% interior false light (of the frame's receiver pixels) reported as
// success before the slope term was bounded. The box's faces a few centimetres from the light
// are seen almost edge-on from it through texels 10 degrees wide, and glPolygonOffset's slope
// term pushed them back past the floor. With the push bounded to 0.3 of each point's depth from
// the light they were within the budget, and so they are with the push bounded to a few
// texels' widths (TechniqueOptions::depth_bias_bound); unbounded at slope 2 without the
// receiver's bias, the second place still fails, so the check sees the fault.
TEST(HardCases, ClosedBoxAroundTheLightMovedDepthMap) {
  for (const glm::vec3 &offset : {kCageOffsets[0], kCageOffsets[1], glm::vec3(-0.3f, 0.45f, -0.5f),
                                  glm::vec3(0.55f, 0.0f, 0.0f)}) {
    expect_these_right_or_refused("k1, the light moved inside the box", cage_with_light_moved(offset),
                                  {"depth-map"}, {}, true);
  }
  gs::Scene receiving = cage_with_light_moved(kCageOffsets[1]);
  receiving.objects[1].receives_shadow = true;  // the cage: its faces then take the facet bias
  expect_these_right_or_refused("k1, the light moved, the box receiving", receiving, {"depth-map"},
                                {}, true);
  const gs::Scene scene = cage_with_light_moved(kCageOffsets[1]);
  const Truth truth = truth_of(scene);
  gs::TechniqueOptions unbounded;  // the push before any bound: slope 2, no receiver bias
  unbounded.depth_bias_bound = INFINITY;
  unbounded.depth_bias_slope = 2.0f;
  unbounded.depth_bias_receiver = 0.0f;
  const Outcome o = run("depth-map", scene, truth, unbounded);
  report("k1, the light moved, depth-map unbounded", o);
  EXPECT_GT(o.errors.false_light_interior, 0.05);  // a share: 16% measured
  // A bound below 0 would slide the copy nearer the light than the caster: refused with a
  // warning, and the frame drawn unbounded (the same fault).
  gs::TechniqueOptions negative = unbounded;
  negative.depth_bias_bound = -0.5f;
  const Outcome refused = run("depth-map", scene, truth, negative);
  ASSERT_FALSE(refused.warnings.empty());
  EXPECT_NE(refused.warnings[0].find("slope bound of -0.5"), std::string::npos) << refused.warnings[0];
  EXPECT_GT(refused.errors.false_light_interior, 0.05);
}

// y6: the light moved inside an open tube (a 170-degree cone, 128 texels): the tube's walls, seen
// almost edge-on, were pushed past the floor outside it (1.012% of the receiver pixels, and 0.251%
// with the light moved again, reported as success). Bounded as k1 above.
TEST(HardCases, TubeAroundTheLightMovedDepthMap) {
  const std::string file = "audit/y6_light_inside_tube_moved.json";
  expect_these_right_or_refused(file, load(file), {"depth-map"}, {}, true);
  gs::Scene moved = load(file);
  moved.lights[0].position += glm::vec3(0.5f, -0.3f, 0.3f);
  expect_these_right_or_refused("y6, the light moved again", moved, {"depth-map"}, {}, true);
}

}  // namespace

// Light 0 inside a closed ball that receives, light 1 outside: light 0 reaches nothing beyond
// the ball, so the floor and the crate are dark to it. The projected techniques draw the ball
// from both sides for light 0 (the floor is wholly outside the ball). The light moved inside the
// ball and the cone narrowed and widened.
TEST(HardCases, BallAroundOneOfTwoLights) {
  expect_right_or_refused("audit/u2_ball_round_light_two_lights.json", {}, false);
  for (const float cone : {40.0f, 140.0f}) {
    gs::Scene scene = load("audit/u2_ball_round_light_two_lights.json");
    scene.lights[0].cone_degrees = cone;
    scene.lights[0].position += glm::vec3(0.2f, -0.15f, 0.1f);
    expect_right_or_refused("u2, cone " + std::to_string(cone), scene, {}, false);
  }
}

// A closed room around the light and the camera, the floor running out under its walls: lit
// inside, dark outside. One texture cannot tell the floor inside from the floor beyond, so the
// projected techniques refuse by name; the others are right.
TEST(HardCases, RoomAroundTheLightWithTheFloorThroughItsWalls) {
  const std::map<std::string, std::string> refusals = {
      {"projected", "light 0 and 'room': the light is inside the caster and 'floor' reaches"},
      {"projected-chroma", "light 0 and 'room': the light is inside the caster and 'floor'"}};
  expect_right_or_refused("audit/u1_light_in_room.json", refusals);
}

// A plate buried whole in the slab of a shelf that is one mesh with the floor (casting nothing):
// the shelf's top, in front of the plate, stays lit; the floor under it takes the plate's shadow.
// The projected techniques serve the two layers with two textures: the shelf's top the one
// masked by its nearest surface, the floor the shelf hides from the light the one masked by its
// farthest (receiver_coords.cpp, depth band -2). Before: the shelf's top shaded with the
// plate's shadow (1.49% interior false shadow, success), then refused by name. The light also
// moved 1 m either way along the shelf.
TEST(HardCases, PlateBuriedInAShelfShadowsOnlyTheFloor) {
  expect_right_or_refused("audit/w2_plate_buried_in_shelf.json");
  for (const float along : {-1.0f, 1.0f}) {
    gs::Scene scene = load("audit/w2_plate_buried_in_shelf.json");
    scene.lights[0].position.z += along;
    expect_right_or_refused("w2, the light moved " + std::to_string(along) + " m", scene);
  }
}

namespace {

// A copy of `file` with the camera and the light moved (world metres).
gs::Scene moved(const std::string &file, const glm::vec3 &camera, const glm::vec3 &light) {
  gs::Scene scene = load(file);
  scene.camera.position += camera;
  scene.lights[0].position += light;
  return scene;
}

}  // namespace

// y3: the floor seen from 0.3 m with the near plane at 0.5 m. Covers over receivers the camera
// clipped reach the W-buffer's ceiling (1/w = 1 at the near plane), and the shim's per-vertex
// clamp there drained their margin: wedges of missing shadow next to the near plane's line
// (0.305% of the receiver pixels, interior, reported as success). Also with the camera and the
// light moved (0.225% before the fix).
TEST(HardCases, PlanarCoversNextToTheNearPlane) {
  const std::string file = "audit/y3_eye_near_plane_light_moved.json";
  expect_these_right_or_refused(file, load(file), {"planar"}, {}, true);
  expect_these_right_or_refused(
      "y3, camera and light moved",
      moved(file, glm::vec3(-0.3f, 0.05f, 0.2f), glm::vec3(0.5f, 0.3f, -0.4f)), {"planar"}, {},
      true);
}

// y4: the posts' and the ball's shadows on floor triangles that reach past the screen's edge,
// near the camera. The shim clips those to the window and snaps the vertices it makes, so the
// floor's depth there strays from its plane by up to 1/32 px of its gradient; the 2-code cover
// failed on single pixels (0.100%). Also with the camera and the light moved (0.171% before the
// fix).
TEST(HardCases, PlanarCoversOverReceiversPastTheScreenEdge) {
  const std::string file = "audit/y4_terminator_posts_light_raised.json";
  expect_these_right_or_refused(file, load(file), {"planar"}, {}, true);
  expect_these_right_or_refused(
      "y4, camera and light moved",
      moved(file, glm::vec3(0.5f, 0.1f, 0.2f), glm::vec3(0.0f, 0.6f, 0.0f)), {"planar"}, {},
      true);
}
