// The depth-map technique on small scenes whose answer is known: the box's footprint (as the
// projected technique finds it), no acne on a lit plane, no light leak under a resting box, a
// receiver between light and caster lit, nothing behind the light shadowed, both filters.
#include "techniques/depth_map/depth_map_shadow.h"
#include "techniques/light_passes/scene_pass.h"

#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include "technique_fixture.h"
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace {


int green6(FxU16 p) { return (p >> 5) & 0x3F; }  // 565 green, the finest channel

class DepthMapShadowTest : public TechniqueTest {
 protected:


  static gs::TechniqueOptions options(bool linear = true) {
    gs::TechniqueOptions o;
    o.depth_map_linear = linear;
    return o;
  }

  // The frame, expecting no warnings.
  static std::vector<FxU16> frame(const gs::Scene &scene, const gs::TechniqueOptions &o) {
    const gs::FrameReport report = gs::make_depth_map_shadow(o)->render(scene, false);
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
    return back_buffer();
  }

  static std::vector<bool> mask_of(gs::ShadowTechnique &technique, const gs::Scene &scene,
                                   bool expect_warnings = false) {
    const gs::FrameReport report = technique.render(scene, false);
    if (!expect_warnings) {
      EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
    }
    technique.render_mask(scene);
    std::vector<bool> mask;
    for (FxU16 p : back_buffer()) {
      EXPECT_TRUE(p == 0 || p == 0xFFFF) << "mask pixel " << p << " neither black nor white";
      mask.push_back(p != 0);
    }
    return mask;
  }

  static std::vector<bool> shadow_mask(const gs::Scene &scene, bool linear = true) {
    return mask_of(*gs::make_depth_map_shadow(options(linear)), scene);
  }



  // The pixel a world point lands on (Glide screen, rows from the top).
  static std::size_t pixel_at(const gs::Scene &scene, const glm::vec3 &world) {
    const glm::vec4 clip = gs::camera_projection(scene.camera, kWidth, kHeight) *
                           gs::camera_view(scene.camera) * glm::vec4(world, 1.0f);
    const GrVertex v = gs::to_screen(clip, kWidth, kHeight);
    return static_cast<std::size_t>(static_cast<int>(v.y) * kWidth + static_cast<int>(v.x));
  }


};

TEST_F(DepthMapShadowTest, ReportsItsThreeSteps) {
  const gs::FrameReport report =
      gs::make_depth_map_shadow(options())->render(box_over_floor(), true);
  ASSERT_EQ(report.steps.size(), 3u);
  EXPECT_EQ(report.steps[0].first, "1 depth from the light");
  EXPECT_EQ(report.steps[1].first, "2 ambient pass");
  EXPECT_EQ(report.steps[2].first, "3 lit pass with the depth test");
  EXPECT_TRUE(report.warnings.empty());
  EXPECT_GT(report.total_ms, 0.0);
}

TEST_F(DepthMapShadowTest, ShadowIsTheBoxFootprintAsTheProjectedTechniqueFindsIt) {
  const gs::Scene scene = box_over_floor();
  const std::vector<bool> mask = shadow_mask(scene);
  std::string error;
  const std::unique_ptr<gs::ShadowTechnique> projected =
      gs::make_technique("projected", options(), error);
  ASSERT_TRUE(projected) << error;
  // (It warns that a 256x256 texture takes the direct path in a 320x240 window.)
  const std::vector<bool> expected = mask_of(*projected, scene, true);
  ASSERT_GT(count(expected), 200);
  EXPECT_GE(count(mask, expected), 0.9 * count(mask)) << "shadow where the projected one has none";
  EXPECT_GE(count(mask, expected), 0.9 * count(expected))
      << "no shadow where the projected one has";
  EXPECT_EQ(count(mask, coverage(scene, 1)), 0) << "the box's lit faces are shadowed";
}

TEST_F(DepthMapShadowTest, NoAcneOnALitPlaneAtTheDefaultBias) {
  // An empty floor (its own caster) with the light 60 degrees from its normal.
  gs::Scene scene = box_over_floor();
  scene.objects.pop_back();
  scene.lights[0].position = {6.0f * std::sin(glm::radians(60.0f)),
                              6.0f * std::cos(glm::radians(60.0f)), 0};
  for (bool linear : {false, true}) {
    EXPECT_EQ(count(shadow_mask(scene, linear)), 0) << (linear ? "linear" : "nearest");
    // The lit part of the frame is brighter than the ambient floor: the light does reach it.
    const std::vector<FxU16> lit = frame(scene, options(linear));
    EXPECT_GT(green6(lit[pixel_at(scene, {0, 0, 0})]), 20);
  }
}

TEST_F(DepthMapShadowTest, NoLightLeaksUnderABoxRestingOnTheFloor) {
  // A 10 cm slab on the floor, the light up on the left: the shadow starts at the slab's right
  // side (x = 0.5), where the slab's top is about 13 cm nearer the light than the floor, so a
  // bias of that much would let light under it.
  gs::Scene scene = box_over_floor();
  scene.objects[1] = object("slab", gs::make_box({0.5f, 0.05f, 0.5f}), {0, 0.05f, 0});
  scene.lights[0].position = {-4.0f, 5.0f, 0};
  scene.camera.position = {4.0f, 3.0f, 5.0f};
  scene.camera.target = {0.5f, 0, 0};
  const std::vector<bool> mask = shadow_mask(scene);
  const std::vector<bool> floor = coverage(scene, 0);
  // Floor points 2..6 cm from the base on the far side, in the 9 cm shadow (a pixel is about
  // 2.5 cm here).
  int visible = 0, shadowed = 0;
  for (float x = 0.52f; x <= 0.565f; x += 0.02f) {
    for (float z = -0.4f; z <= 0.4f; z += 0.05f) {
      const std::size_t p = pixel_at(scene, {x, 0, z});
      if (!floor[p]) continue;
      ++visible;
      shadowed += mask[p];
    }
  }
  ASSERT_GT(visible, 40);
  EXPECT_GE(shadowed, 0.97 * visible)
      << shadowed << " of " << visible << ": light leaks under the slab";
  // And the near side, lit, stays lit.
  for (float z = -0.4f; z <= 0.4f; z += 0.1f) EXPECT_FALSE(mask[pixel_at(scene, {-0.6f, 0, z})]);
}

TEST_F(DepthMapShadowTest, NothingBetweenTheLightAndTheCasterIsShadowed) {
  gs::Scene scene = box_over_floor();
  scene.objects.push_back(object("plate", gs::make_box({0.8f, 0.02f, 0.8f}), {0.3f, 3.5f, 0}));
  scene.objects[2].casts_shadow = false;
  const std::vector<bool> mask = shadow_mask(scene);
  EXPECT_EQ(count(mask, coverage(scene, 2)), 0) << "receiver between light and caster darkened";
  EXPECT_GT(count(mask, coverage(scene, 0)), 100);
}

TEST_F(DepthMapShadowTest, NothingBehindTheLightIsShadowed) {
  // The light 1 m over a floor made of two triangles, looking along +x at the caster. The floor
  // behind the light (x < 0) shares triangles with the lit part in front, so it gets some of
  // their light by interpolation; its texture coordinates there mirror the caster back (q < 0).
  gs::Scene scene;
  scene.width = kWidth, scene.height = kHeight;
  scene.objects.push_back(object("caster", gs::make_box(glm::vec3(0.4f)), {2.0f, 1.0f, 0}));
  scene.objects.push_back(
      object("wall behind", gs::make_box({0.05f, 2.0f, 2.0f}), {-2.0f, 1.0f, 0}));
  scene.objects.push_back(
      object("wall beyond", gs::make_box({0.05f, 2.0f, 2.0f}), {4.0f, 1.0f, 0}));
  scene.objects.push_back(object("floor", gs::make_plane(12.0f, 1), {0, 0, 0}));
  for (std::size_t i = 1; i < scene.objects.size(); ++i) scene.objects[i].casts_shadow = false;
  gs::SpotLight light;
  light.position = {0.0f, 1.0f, 0};
  light.target = {2.0f, 1.0f, 0};
  light.cone_degrees = 170.0f;
  scene.lights.push_back(light);
  scene.camera.position = {0.0f, 5.0f, 12.0f};
  scene.camera.target = {0.0f, 0.5f, 0};
  const std::vector<bool> mask = shadow_mask(scene);
  EXPECT_EQ(count(mask, coverage(scene, 1)), 0) << "shadow projected behind the light";
  EXPECT_GT(count(mask, coverage(scene, 2)), 20) << "no shadow on the wall beyond the caster";
  // Floor pixels behind the light: left of the line x = -0.1 on the floor.
  const std::vector<bool> floor = coverage(scene, 3);
  const std::size_t a = pixel_at(scene, {-0.1f, 0, -6}), b = pixel_at(scene, {-0.1f, 0, 6});
  const int ax = static_cast<int>(a % kWidth), ay = static_cast<int>(a / kWidth);
  const int bx = static_cast<int>(b % kWidth), by = static_cast<int>(b / kWidth);
  int behind = 0, shadowed_behind = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const auto p = static_cast<std::size_t>(y * kWidth + x);
      if (!floor[p] || (bx - ax) * (y - ay) - (by - ay) * (x - ax) <= 0) continue;
      ++behind;
      shadowed_behind += mask[p];
    }
  }
  ASSERT_GT(behind, 5000);
  EXPECT_EQ(shadowed_behind, 0) << "floor behind the light shadowed (back projection)";
}

TEST_F(DepthMapShadowTest, NearestGivesTwoLevelsAndLinearIntermediateOnesAtTheEdge) {
  // Against the frame with nothing casting (lit everywhere) and with no light (ambient only):
  // nearest lookups give every pixel one of the two; linear (percentage-closer) ones give
  // levels in between along the shadow's edge.
  const gs::Scene scene = box_over_floor();
  gs::Scene unshadowed = scene, dark = scene;
  for (gs::SceneObject &o : unshadowed.objects) o.casts_shadow = false;
  dark.lights.clear();
  const std::vector<FxU16> lit = frame(unshadowed, options()), ambient = frame(dark, options());
  int differ = 0;
  for (std::size_t i = 0; i < lit.size(); ++i) differ += lit[i] != ambient[i];
  ASSERT_GT(differ, 10000) << "the light hardly shows";
  auto intermediate = [&](const std::vector<FxU16> &pixels) {
    int n = 0;
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      const int g = green6(pixels[i]), g_lit = green6(lit[i]), g_dark = green6(ambient[i]);
      n += g > std::min(g_lit, g_dark) && g < std::max(g_lit, g_dark);
    }
    return n;
  };
  int other = 0;
  const std::vector<FxU16> nearest = frame(scene, options(false));
  for (std::size_t i = 0; i < nearest.size(); ++i)
    other += nearest[i] != lit[i] && nearest[i] != ambient[i];
  EXPECT_EQ(other, 0) << "nearest lookups gave levels other than lit and unlit";
  // A 32-texel map, so the percentage-closer ramp (a texel wide) spans pixels: the map's frustum
  // is fitted to the box (issue 14), whose shadow a 256-texel map resolves finer than a pixel.
  gs::TechniqueOptions coarse = options(true);
  coarse.projected.size = 32;
  EXPECT_GT(intermediate(frame(scene, coarse)), 20) << "no percentage-closer edge";
}

TEST_F(DepthMapShadowTest, AConeTooWideForAFrustumIsReportedAndLeftUnshadowed) {
  gs::Scene scene = box_over_floor();
  scene.lights[0].cone_degrees = 179.5f;
  const std::unique_ptr<gs::ShadowTechnique> technique = gs::make_depth_map_shadow(options());
  const gs::FrameReport report = technique->render(scene, false);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("light 0"), std::string::npos) << report.warnings[0];
  const std::vector<FxU16> pixels = back_buffer();
  EXPECT_GT(green6(pixels[pixel_at(scene, {0, 0, 2})]), 20) << "the light itself went missing";
  technique->render_mask(scene);
  for (FxU16 p : back_buffer()) ASSERT_EQ(p, 0) << "a light without a map shadowed something";
}

}  // namespace
