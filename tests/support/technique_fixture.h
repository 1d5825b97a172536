// Shared by the technique tests: a 320x240 Glide window per test, the frame and a technique's
// shadow mask read back as pixel sets, which pixels an object covers, and the reference scene of
// a box over a floor under a light straight above.
#pragma once

#include "scene/scene.h"
#include "techniques/technique.h"

#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

// Scene builders, also for tests that need no Glide window.
gs::SceneObject placed_object(const std::string &name, gs::Mesh mesh, const glm::vec3 &at);
// A 1 m box centred 1.5 m above a 10 m floor (which casts nothing), the light straight above
// at 8 m, the camera looking down at about 45 degrees; a width x height screen.
gs::Scene box_over_floor_scene(int width, int height);

class TechniqueTest : public ::testing::Test {
 public:
  static constexpr int kWidth = 320, kHeight = 240;

 protected:
  using Mask = std::vector<bool>;  // one flag per pixel, rows from the top

  void SetUp() override;
  void TearDown() override;

  static std::vector<FxU16> back_buffer();
  static Mask white_pixels();  // non-zero pixels of the back buffer
  // The technique's frame, then its mask (which pixels it darkened).
  static Mask mask_of(gs::ShadowTechnique &technique, const gs::Scene &scene,
                      gs::FrameReport *report = nullptr);
  // Pixels where object `index` is the visible surface (the scene lit flat, that object white).
  static Mask coverage(gs::Scene scene, std::size_t index);
  static int count(const Mask &a);
  static int count(const Mask &a, const Mask &b);  // pixels in both
  static Mask both(const Mask &a, const Mask &b);

  static gs::SceneObject object(const std::string &name, gs::Mesh mesh, const glm::vec3 &at) {
    return placed_object(name, std::move(mesh), at);
  }
  static gs::Scene box_over_floor() { return box_over_floor_scene(kWidth, kHeight); }
};
