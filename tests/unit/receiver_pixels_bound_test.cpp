// receiver_screen_pixels_at_least (texel_error/shadow_edge_error.h): a lower bound of the
// edge-error budget's base from the large triangles wholly on the screen side of the camera,
// stopping once enough pixels are covered; never above receiver_screen_pixels.
#include "scene/fight_scene.h"
#include "techniques/geometry/projection.h"
#include "techniques/texel_error/shadow_edge_error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

TEST(ReceiverPixelsBound, NeverAboveTheCountAndShrinksWithTheLeastArea) {
  gs::FightScene fight(640, 480, 256);
  for (float time : {0.0f, 1.3f, 4.7f}) {
    const gs::Scene &scene = fight.at(time);
    const gs::FrameGeometry frame = gs::project_scene(scene);
    const float all = gs::receiver_screen_pixels(scene, frame);
    float previous = INFINITY;
    for (float least_area : {0.001f, 16.0f, 64.0f, 1000.0f}) {
      const float bound = gs::receiver_screen_pixels_at_least(scene, frame, least_area, INFINITY);
      EXPECT_LE(bound, all) << "time " << time << ", least area " << least_area;
      EXPECT_LE(bound, previous) << "a larger least area covers a subset";
      previous = bound;
    }
    // The ring's mat and apron are large triangles: most of the count without the fighters'.
    EXPECT_GT(gs::receiver_screen_pixels_at_least(scene, frame, 64.0f, INFINITY), 0.5f * all);
  }
}

TEST(ReceiverPixelsBound, StopsOnceEnoughAreCovered) {
  gs::FightScene fight(640, 480, 256);
  const gs::Scene &scene = fight.at(2.0f);
  const gs::FrameGeometry frame = gs::project_scene(scene);
  const float whole = gs::receiver_screen_pixels_at_least(scene, frame, 64.0f, INFINITY);
  ASSERT_GT(whole, 20000.0f);
  const float some = gs::receiver_screen_pixels_at_least(scene, frame, 64.0f, 5000.0f);
  EXPECT_GE(some, 5000.0f);
  EXPECT_LT(some, whole) << "it went on past enough";
  EXPECT_EQ(gs::receiver_screen_pixels_at_least(scene, frame, 64.0f, 0.0f), 0.0f)
      << "nothing is needed, nothing is covered";
  EXPECT_EQ(gs::receiver_screen_pixels_at_least(scene, frame, 64.0f, NAN), 0.0f);
}

// A scene wholly on the screen: with every triangle large enough, the bound is the count.
TEST(ReceiverPixelsBound, EveryTriangleCoveredIsTheCount) {
  gs::FightScene fight(640, 480, 256);
  gs::Scene scene = fight.at(0.0f);
  // From far enough that the whole scene lies on the screen, before the far plane.
  scene.camera.position = scene.camera.target + 4.0f * (scene.camera.position - scene.camera.target);
  const gs::FrameGeometry frame = gs::project_scene(scene);
  bool inside = true;
  for (const gs::ProjectedObject &object : frame.objects)
    for (unsigned outside : object.outside) inside = inside && outside == 0;
  const float all = gs::receiver_screen_pixels(scene, frame);
  const float bound = gs::receiver_screen_pixels_at_least(scene, frame, 1e-30f, INFINITY);
  ASSERT_TRUE(inside) << "the ring reaches past the guard band: the test tests nothing";
  EXPECT_EQ(bound, all);
}

}  // namespace
