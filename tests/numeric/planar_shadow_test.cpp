// The planar shadow technique (projected and clipped polygons) on small scenes whose answer is
// known: the footprint of a box against its geometric shadow, no shadow on the caster or on a
// receiver nearer the light, shadows on other objects, agreement with the projected texture, each
// pixel darkened once however many polygons cover it, and the pair limit's warning.
#include "scene/fight_scene.h"
#include "techniques/planar/planar_shadow.h"
#include "techniques/light_passes/scene_pass.h"
#include "techniques/technique.h"

#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include "technique_fixture.h"
#include <glm/gtc/matrix_transform.hpp>

#include <map>

namespace {


class PlanarShadowTest : public TechniqueTest {
 protected:


  static std::vector<bool> nonzero(const std::vector<FxU16> &pixels) {
    std::vector<bool> set;
    for (FxU16 p : pixels) set.push_back(p != 0);
    return set;
  }

  // Which pixels a technique darkened (white in its render_mask).
  static std::vector<bool> shadow_mask(const gs::Scene &scene, const std::string &name = "planar",
                                       gs::FrameReport *report = nullptr) {
    std::unique_ptr<gs::ShadowTechnique> technique = make(name);
    const gs::FrameReport frame = technique->render(scene, false);
    technique->render_mask(scene);
    if (report != nullptr) *report = frame;
    return nonzero(back_buffer());
  }

  static std::unique_ptr<gs::ShadowTechnique> make(const std::string &name) {
    if (name == "planar") return gs::make_planar_shadow({});
    std::string error;
    std::unique_ptr<gs::ShadowTechnique> technique = gs::make_technique(name, {}, error);
    EXPECT_TRUE(technique) << error;
    return technique;
  }


  // A world-space polygon alone, white on black through the scene's camera (no depth test).
  static std::vector<bool> polygon_pixels(const gs::Scene &scene,
                                          const std::vector<glm::vec3> &corners) {
    const gs::FrameGeometry frame = gs::project_scene(scene);
    grBufferClear(0, 0, GR_WDEPTHVALUE_FARTHEST);
    grDepthBufferMode(GR_DEPTHBUFFER_DISABLE);
    grCullMode(GR_CULL_DISABLE);
    grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                   GR_COMBINE_OTHER_NONE, FXFALSE);
    grConstantColorValue(0xFFFFFFFFu);
    std::vector<gs::ClipVertex> polygon, scratch;
    for (const glm::vec3 &corner : corners) polygon.push_back({{}, corner, {}});
    std::vector<GrVertex> screen;
    gs::project_camera_polygon(frame, scene, polygon, scratch, screen);
    gs::draw_fan(screen);
    gs::set_scene_state();
    return nonzero(back_buffer());
  }

  // Pixels of `a` whose 3x3 neighbourhood is all in `a`: the region without its edge pixels.
  static std::vector<bool> interior(const std::vector<bool> &a) {
    std::vector<bool> out(a.size(), false);
    for (int y = 1; y < kHeight - 1; ++y) {
      for (int x = 1; x < kWidth - 1; ++x) {
        bool all = true;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) all = all && a[static_cast<std::size_t>((y + dy) * kWidth + x + dx)];
        out[static_cast<std::size_t>(y * kWidth + x)] = all;
      }
    }
    return out;
  }
  static glm::vec2 centroid(const std::vector<bool> &a) {
    glm::dvec2 sum(0.0);
    int n = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        if (a[static_cast<std::size_t>(y * kWidth + x)]) sum += glm::dvec2(x, y), ++n;
    return glm::vec2(sum / static_cast<double>(std::max(n, 1)));
  }


};

TEST_F(PlanarShadowTest, BoxShadowIsItsGeometricFootprint) {
  // Straight below the light only the box's top face (y = 2) faces it; its outline projects to a
  // square of side 1 * 8 / (8 - 2) = 4/3 m centred under the box. The box hides part of that
  // square from the camera, so the expectation is the square where the floor is visible.
  const gs::Scene scene = box_over_floor();
  const float half = 0.5f * 8.0f / 6.0f;
  const std::vector<bool> square =
      polygon_pixels(scene, {{-half, 0, -half}, {-half, 0, half}, {half, 0, half}, {half, 0, -half}});
  const std::vector<bool> expected = both(square, coverage(scene, 0));
  const std::vector<bool> mask = shadow_mask(scene);
  const int expected_count = count(expected), mask_count = count(mask);
  ASSERT_GT(expected_count, 1000);
  // Within a few percent: the square's outline is about 4% of its pixels, and the polygons'
  // 1/16-pixel vertex snap or the box's edge may move it by a pixel.
  EXPECT_NEAR(mask_count, expected_count, 0.03 * expected_count);
  EXPECT_GE(count(mask, expected), expected_count * 97 / 100) << "part of the footprint unshadowed";
  EXPECT_GE(count(mask, expected), mask_count * 97 / 100) << "shadow outside the footprint";
  const glm::vec2 offset = centroid(mask) - centroid(expected);
  EXPECT_LT(glm::length(offset), 1.0f) << "shadow off centre by " << offset.x << ", " << offset.y;
}

TEST_F(PlanarShadowTest, CasterGetsNoShadowOfItsOwn) {
  // An L-shaped caster floating over the floor: a pillar beside a slab, the light low on the
  // pillar's side, so the pillar's triangles would shadow the whole top of the slab if a caster
  // received its own shadow (a convex caster never could: its other faces are all behind).
  gs::Scene scene = box_over_floor();
  gs::Mesh l_shape = gs::make_box({0.6f, 0.1f, 0.4f});  // the slab, x from -0.4 to 0.8
  l_shape.append(gs::make_box({0.2f, 0.8f, 0.2f}),
                 glm::translate(glm::mat4(1.0f), {-0.6f, 0.7f, 0.0f}));  // the pillar
  scene.objects[1] = object("L", l_shape, {0, 1.2f, 0});
  scene.lights[0].position = {-5.0f, 6.0f, 1.0f};
  scene.lights[0].target = {0, 0, 0};
  const std::vector<bool> mask = shadow_mask(scene);
  EXPECT_GT(count(mask, coverage(scene, 0)), 1000) << "no shadow on the floor";
  // The caster stands on the floor: a cover on the floor passes the caster's own pixels where
  // the two lie within the cover's margin (2 W-buffer codes, planar_shadow.cpp) of each other,
  // a pixel of the contact line at most; a shadow of the caster on itself would be hundreds.
  EXPECT_LE(count(mask, coverage(scene, 1)), 1) << "the caster shadows itself";
}

TEST_F(PlanarShadowTest, NothingBetweenTheLightAndTheCasterIsShadowed) {
  // A thin plate between the light and the box: it must stay lit; the floor still gets a shadow.
  gs::Scene scene = box_over_floor();
  scene.objects.push_back(object("plate", gs::make_box({0.8f, 0.02f, 0.8f}), {0.3f, 3.5f, 0}));
  scene.objects[2].casts_shadow = false;
  const std::vector<bool> mask = shadow_mask(scene);
  EXPECT_EQ(count(mask, coverage(scene, 2)), 0) << "receiver between light and caster darkened";
  EXPECT_GT(count(mask, coverage(scene, 0)), 1000);
}

TEST_F(PlanarShadowTest, ShadowFallsOnAnotherObject) {
  // The light low on the left: the tall caster's shadow reaches the box on the right.
  gs::Scene scene = box_over_floor();
  scene.objects[1] = object("caster", gs::make_box({0.3f, 1.0f, 0.3f}), {-1.0f, 1.0f, 0});
  scene.objects.push_back(object("receiver", gs::make_box({0.4f, 0.8f, 0.8f}), {1.2f, 0.8f, 0}));
  scene.objects[2].casts_shadow = false;
  scene.lights[0].position = {-6.0f, 2.2f, 0};
  scene.lights[0].target = {1.0f, 0.8f, 0};
  scene.camera.position = {0, 3, 7};
  const std::vector<bool> receiver = coverage(scene, 2);
  const std::vector<bool> mask = shadow_mask(scene);
  // The 0.6 m wide caster leaves a band across the receiver's lit side: a few percent of the
  // receiver's ~1,000 pixels at the least.
  EXPECT_GT(count(mask, receiver), 40) << "no shadow on the other object";
  // The caster stands on the floor: a cover on the floor passes the caster's own pixels where
  // the two lie within the cover's margin (2 W-buffer codes, planar_shadow.cpp) of each other,
  // a pixel of the contact line at most; a shadow of the caster on itself would be hundreds.
  EXPECT_LE(count(mask, coverage(scene, 1)), 1) << "the caster shadows itself";
}

TEST_F(PlanarShadowTest, AgreesWithTheProjectedTexture) {
  // Same shadow up to edge pixels: the texture's are bilinear and 256 texels across the caster's
  // view, the polygons' exact.
  const gs::Scene scene = box_over_floor();
  const std::vector<bool> planar = shadow_mask(scene);
  const std::vector<bool> projected = shadow_mask(scene, "projected");
  const int both_count = count(planar, projected);
  ASSERT_GT(count(planar), 1000);
  EXPECT_GE(both_count, count(planar) * 9 / 10) << "planar shadow outside the projected one";
  EXPECT_GE(both_count, count(projected) * 9 / 10) << "projected shadow outside the planar one";
}

TEST_F(PlanarShadowTest, OverlappingShadowsDarkenOnce) {
  // Two boxes at different heights whose shadows overlap on a uniformly lit floor (ambient only,
  // the light's colour black: its shadows still blend at its strength). Where both shadows fall,
  // the floor must be exactly as dark as where one does.
  gs::Scene scene = box_over_floor();
  scene.objects[1] = object("low box", gs::make_box(glm::vec3(0.5f)), {-0.3f, 1.5f, 0});
  scene.objects.push_back(object("high box", gs::make_box(glm::vec3(0.5f)), {0.3f, 2.8f, 0.2f}));
  scene.objects[1].receives_shadow = scene.objects[2].receives_shadow = false;
  scene.ambient = glm::vec3(0.6f);
  scene.lights[0].position = {0, 8, -2};  // the shadows thrown forward, out from behind the boxes
  scene.lights[0].color = glm::vec3(0.0f);
  gs::Scene only_low = scene, only_high = scene;
  only_low.objects[2].casts_shadow = false;
  only_high.objects[1].casts_shadow = false;
  const std::vector<bool> low = shadow_mask(only_low), high = shadow_mask(only_high);
  std::vector<bool> one(low.size()), two(low.size());
  for (std::size_t i = 0; i < low.size(); ++i) one[i] = low[i] != high[i], two[i] = low[i] && high[i];
  one = interior(one);
  two = interior(two);
  ASSERT_GT(count(one), 300);
  ASSERT_GT(count(two), 300);

  make("planar")->render(scene, false);
  const std::vector<FxU16> frame = back_buffer();
  std::map<FxU16, int> single_values;
  for (std::size_t i = 0; i < frame.size(); ++i) if (one[i]) single_values[frame[i]]++;
  ASSERT_EQ(single_values.size(), 1u) << "the single shadow is not uniform";
  const FxU16 single = single_values.begin()->first;
  int darker = 0;
  for (std::size_t i = 0; i < frame.size(); ++i) darker += two[i] && frame[i] != single;
  EXPECT_EQ(darker, 0) << "of " << count(two) << " overlap pixels, " << darker
                       << " differ from the single shadow's 0x" << std::hex << single;
}

TEST_F(PlanarShadowTest, FightersShadowTheRingAndEachOther) {
  // The light is low behind the attacker (red until 3.1 s, blue from 3.7 s): its shadow must
  // reach the other fighter; the attacker, nearer the light, gets none. A shadow on the mat
  // starts at the caster's soles, which lie within the polygons' two W-buffer codes of the mat
  // at a pixel or three of the contact: those pass the depth test on the foot, so up to three
  // such pixels are allowed (measured: 3 at 5.3 s).
  gs::FightScene fight(kWidth, kHeight, 128);
  for (float time : {0.0f, 1.0f, 5.3f, 6.5f}) {
    const gs::Scene &scene = fight.at(time);
    const float side = gs::fight_light_side(time);
    ASSERT_TRUE(side == 0.0f || side == 1.0f) << "time " << time << ": the light is swinging";
    const std::size_t near_fighter = gs::FightScene::kFighters[side == 0.0f ? 0 : 1];
    const std::size_t far_fighter = gs::FightScene::kFighters[side == 0.0f ? 1 : 0];
    gs::FrameReport report;
    const std::vector<bool> mask = shadow_mask(scene, "planar", &report);
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
    ASSERT_EQ(report.steps.size(), 3u);
    EXPECT_EQ(report.steps[0].first, "1 project and clip caster polygons");
    EXPECT_GT(count(mask, coverage(scene, gs::FightScene::kRing)), 200)
        << "time " << time << ": no shadow on the ring";
    EXPECT_GT(count(mask, coverage(scene, far_fighter)), 20)
        << "time " << time << ": the attacker's shadow misses the other fighter";
    EXPECT_LE(count(mask, coverage(scene, near_fighter)), 3)
        << "time " << time << ": shadow on the fighter nearer the light";
  }
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

TEST_F(PlanarShadowTest, TooManyPairsAreReportedOnceAndTheRestStillCast) {
  // A finely sliced cylinder lying diagonally over a finely divided floor: every long side
  // triangle's box in the light's view spans thousands of floor triangles, millions of pairs.
  gs::Scene scene = box_over_floor();
  scene.objects[0].mesh = gs::make_plane(10.0f, 200);
  scene.objects[1] = object("log", gs::make_cylinder(0.3f, 3.0f, 1000, true), {0, 0, 0});
  scene.objects[1].model_to_world =
      glm::rotate(glm::rotate(glm::translate(glm::mat4(1.0f), {-1.0f, 1.5f, -1.0f}),
                              glm::radians(45.0f), glm::vec3(0, 1, 0)),
                  glm::radians(90.0f), glm::vec3(1, 0, 0));
  const gs::PlanarShadows shadows = gs::project_and_clip_casters(scene);
  EXPECT_EQ(shadows.pairs_clipped, gs::kMaxClippedPairs);
  EXPECT_GT(shadows.pairs_skipped, 0u);
  gs::FrameReport report;
  const std::vector<bool> mask = shadow_mask(scene, "planar", &report);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("limit"), std::string::npos) << report.warnings[0];
  EXPECT_GT(count(mask, coverage(scene, 0)), 50) << "the pairs within the limit cast nothing";
}

}  // namespace
