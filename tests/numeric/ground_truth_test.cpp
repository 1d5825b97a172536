// The ray-cast ground truth on scenes whose answer is known without it: the analytic shadow of a
// box under a light straight above, a receiver nearer the light than the caster, points behind
// the light, an object shadowing itself, determinism, refusing absurd sizes, and the time it
// takes on the demo's scene. No Glide window: everything here is CPU ray casting.
#include "scene/fight_scene.h"
#include "measure/ground_truth.h"
#include "scene/lighting.h"
#include "techniques/geometry/projection.h"
#include "technique_fixture.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>

namespace {

constexpr int kTruthWidth = 320, kTruthHeight = 240;
constexpr std::size_t kFloor = 0, kBox = 1;

gs::SceneObject object(const std::string &name, gs::Mesh mesh, const glm::vec3 &at) {
  return placed_object(name, std::move(mesh), at);
}

gs::Scene box_over_floor() { return box_over_floor_scene(kTruthWidth, kTruthHeight); }

gs::GroundTruth truth_of(const gs::Scene &scene) {
  gs::GroundTruth truth;
  std::string error;
  EXPECT_TRUE(gs::compute_ground_truth(scene, truth, error)) << error;
  return truth;
}

glm::vec2 to_pixels(const gs::Scene &scene, const glm::vec3 &world) {
  const glm::mat4 vp = gs::camera_projection(scene.camera, scene.width, scene.height) *
                       gs::camera_view(scene.camera);
  const GrVertex v = gs::to_screen(vp * glm::vec4(world, 1.0f), scene.width, scene.height);
  return {v.x, v.y};
}

// Signed distance (pixels) of `p` inside a convex polygon given in either winding: positive
// inside, the smallest over the edges.
double inside_distance(const std::array<glm::vec2, 4> &polygon, const glm::vec2 &p) {
  double area = 0.0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const glm::vec2 &a = polygon[k], &b = polygon[(k + 1) % polygon.size()];
    area += static_cast<double>(a.x) * b.y - static_cast<double>(b.x) * a.y;
  }
  double distance = 1e30;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const glm::dvec2 a(polygon[k]), b(polygon[(k + 1) % polygon.size()]);
    const glm::dvec2 edge = b - a, to_p = glm::dvec2(p) - a;
    const double cross = edge.x * to_p.y - edge.y * to_p.x;
    distance = std::min(distance, (area > 0 ? cross : -cross) / glm::length(edge));
  }
  return distance;
}

// Where the camera ray through pixel (i, j)'s centre meets the plane y = 0, world.
glm::dvec3 floor_point(const gs::Scene &scene, int i, int j) {
  const glm::dmat4 inverse = glm::inverse(
      glm::dmat4(gs::camera_projection(scene.camera, scene.width, scene.height)) *
      glm::dmat4(gs::camera_view(scene.camera)));
  const double x = (i + 0.5) / scene.width * 2.0 - 1.0, y = 1.0 - (j + 0.5) / scene.height * 2.0;
  const glm::dvec4 n = inverse * glm::dvec4(x, y, -1.0, 1.0), f = inverse * glm::dvec4(x, y, 1.0, 1.0);
  const glm::dvec3 a = glm::dvec3(n) / n.w, b = glm::dvec3(f) / f.w;
  return a + (b - a) * (a.y / (a.y - b.y));
}

int count(const std::vector<std::uint8_t> &mask) {
  return static_cast<int>(std::count(mask.begin(), mask.end(), 1));
}

TEST(GroundTruthTest, BoxShadowIsTheAnalyticSquare) {
  const gs::Scene scene = box_over_floor();
  const gs::GroundTruth truth = truth_of(scene);
  ASSERT_EQ(truth.object.size(), static_cast<std::size_t>(kTruthWidth * kTruthHeight));
  ASSERT_EQ(truth.lights, 1u);
  // Only the top face (y = 2) faces the light at y = 8: its shadow on y = 0 has side 1 * 8 / 6.
  const float half = 2.0f / 3.0f;
  const std::array<glm::vec2, 4> square = {
      to_pixels(scene, {-half, 0, -half}), to_pixels(scene, {half, 0, -half}),
      to_pixels(scene, {half, 0, half}), to_pixels(scene, {-half, 0, half})};
  int missing = 0, outside = 0, box_pixels = 0;
  for (int j = 0; j < kTruthHeight; ++j) {
    for (int i = 0; i < kTruthWidth; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * kTruthWidth + i;
      const double d = inside_distance(square, {static_cast<float>(i) + 0.5f, static_cast<float>(j) + 0.5f});
      if (truth.shadow[p] == 1 && (truth.object[p] != int(kFloor) || d < -1.0)) ++outside;
      if (truth.object[p] == int(kFloor) && d > 1.0 && truth.shadow[p] != 1) ++missing;
      if (truth.object[p] == int(kBox)) {
        ++box_pixels;
        EXPECT_EQ(truth.shadow[p], 0) << "box pixel " << i << "," << j;
      }
      EXPECT_EQ(truth.self_shadow[p], 0) << "convex objects cannot shadow themselves";
    }
  }
  EXPECT_GT(box_pixels, 500);
  EXPECT_GT(count(truth.shadow), 500);
  EXPECT_EQ(outside, 0);
  EXPECT_EQ(missing, 0);
}

TEST(GroundTruthTest, LitFloorMatchesTheLightingModel) {
  const gs::Scene scene = box_over_floor();
  const gs::GroundTruth truth = truth_of(scene);
  int checked = 0;
  for (int j = 0; j < kTruthHeight; j += 7) {
    for (int i = 0; i < kTruthWidth; i += 7) {
      const std::size_t p = static_cast<std::size_t>(j) * kTruthWidth + i;
      if (truth.object[p] != int(kFloor) || truth.reach[p] != gs::LightReach::Lit) continue;
      const glm::vec3 expected =
          gs::shade_vertex(scene, glm::vec3(floor_point(scene, i, j)), {0, 1, 0}, glm::vec3(1.0f)) *
          255.0f;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(truth.rgb[3 * p + c], expected[c], 1.0);
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
  const glm::ivec3 background(glm::round(scene.background * 255.0f));
  EXPECT_EQ(truth.object[0], -1) << "the upper-left corner looks past the floor";
  EXPECT_EQ(glm::ivec3(truth.rgb[0], truth.rgb[1], truth.rgb[2]), background);
}

TEST(GroundTruthTest, ReceiverNearerTheLightThanTheCasterIsLit) {
  gs::Scene scene = box_over_floor();
  scene.objects.push_back(object("plate", gs::make_plane(0.6f, 1), {0, 3.5f, 0}));
  const int plate = static_cast<int>(scene.objects.size() - 1);
  const gs::GroundTruth truth = truth_of(scene);
  int plate_pixels = 0, shadowed_box = 0;
  for (std::size_t p = 0; p < truth.object.size(); ++p) {
    if (truth.object[p] == plate) {
      ++plate_pixels;
      EXPECT_EQ(truth.reach[p], gs::LightReach::Lit);
      EXPECT_EQ(truth.shadow[p], 0);
    }
    if (truth.object[p] == int(kBox) && truth.shadow[p] == 1) ++shadowed_box;
  }
  EXPECT_GT(plate_pixels, 100);
  EXPECT_GT(shadowed_box, 100) << "the plate's shadow covers the box's top";
}

TEST(GroundTruthTest, PointsBehindTheLightAreOutside) {
  gs::Scene scene = box_over_floor();
  scene.objects.resize(1);  // the floor only
  scene.lights[0].position = {0, 0.5f, -2};
  scene.lights[0].target = {0, 0.5f, -10};
  const gs::GroundTruth truth = truth_of(scene);
  int behind = 0, in_front = 0;
  for (int j = 0; j < kTruthHeight; ++j) {
    for (int i = 0; i < kTruthWidth; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * kTruthWidth + i;
      if (truth.object[p] != int(kFloor)) continue;
      const glm::dvec3 at = floor_point(scene, i, j);
      if (at.z > -1.9) {
        ++behind;
        EXPECT_EQ(truth.reach[p], gs::LightReach::Outside) << "pixel " << i << "," << j;
      } else if (at.z < -3.5 && std::abs(at.x) < 0.3) {  // well inside the 30° half-angle
        ++in_front;
        EXPECT_EQ(truth.reach[p], gs::LightReach::Lit) << "pixel " << i << "," << j << " at x " << at.x << " z " << at.z;
      }
      EXPECT_EQ(truth.shadow[p], 0);
    }
  }
  EXPECT_GT(behind, 1000);
  EXPECT_GT(in_front, 100);
}

TEST(GroundTruthTest, ObjectShadowingItselfIsSelfShadowOnly) {
  gs::Scene scene = box_over_floor();
  // A slab with a pillar on it, one object: the pillar's shadow falls on the slab.
  gs::Mesh l_shape = gs::make_box({1.5f, 0.1f, 1.5f});
  l_shape.append(gs::make_box({0.25f, 0.75f, 0.25f}),
                 glm::translate(glm::mat4(1.0f), {0.0f, 0.85f, 0.0f}));
  scene.objects[kBox] = object("slab and pillar", l_shape, {0, 0.1f, 0});
  scene.lights[0].position = {3, 8, 0};
  const gs::GroundTruth truth = truth_of(scene);
  int self = 0, floor_shadow = 0;
  for (std::size_t p = 0; p < truth.object.size(); ++p) {
    if (truth.object[p] == int(kBox)) {
      EXPECT_EQ(truth.shadow[p], 0) << "nothing else blocks the light from the slab";
      self += truth.self_shadow[p];
    } else {
      EXPECT_EQ(truth.self_shadow[p], 0);
      floor_shadow += truth.shadow[p];
    }
  }
  EXPECT_GT(self, 200);
  EXPECT_GT(floor_shadow, 100);
}

// casts_shadow false: the object blocks no light, neither another object's nor its own, as no
// technique draws it into a shadow map, a volume or a shadow texture.
TEST(GroundTruthTest, AnObjectThatCastsNoShadowBlocksNoLight) {
  gs::Scene scene = box_over_floor();
  const gs::GroundTruth casting = truth_of(scene);
  ASSERT_GT(count(casting.shadow), 500);
  scene.objects[kBox].casts_shadow = false;
  const gs::GroundTruth silent = truth_of(scene);
  EXPECT_EQ(count(silent.shadow), 0) << "the box still darkens the floor";
  EXPECT_EQ(count(silent.self_shadow), 0);
  EXPECT_EQ(silent.object, casting.object) << "it is still seen";
  for (std::size_t p = 0; p < silent.object.size(); ++p) {
    EXPECT_NE(silent.reach[p], gs::LightReach::Blocked) << "pixel " << p;
  }
  // An object that does not cast does not shadow itself either: the slab-and-pillar of
  // ObjectShadowingItselfIsSelfShadowOnly has no self-shadow once it casts nothing.
  gs::Mesh l_shape = gs::make_box({1.5f, 0.1f, 1.5f});
  l_shape.append(gs::make_box({0.25f, 0.75f, 0.25f}),
                 glm::translate(glm::mat4(1.0f), {0.0f, 0.85f, 0.0f}));
  scene.objects[kBox] = object("slab and pillar", l_shape, {0, 0.1f, 0});
  scene.objects[kBox].casts_shadow = false;
  scene.lights[0].position = {3, 8, 0};
  const gs::GroundTruth slab = truth_of(scene);
  EXPECT_EQ(count(slab.self_shadow), 0);
  EXPECT_EQ(count(slab.shadow), 0);
}

// receives_shadow false: the object is lit wherever the light reaches it, even behind a caster,
// as every technique leaves it unshadowed; other objects still block light from the rest.
TEST(GroundTruthTest, AnObjectThatReceivesNoShadowIsNeverInShadow) {
  gs::Scene scene = box_over_floor();
  scene.objects.push_back(object("plate", gs::make_plane(0.6f, 1), {0, 3.5f, 0}));
  const int plate = static_cast<int>(scene.objects.size() - 1);
  const gs::GroundTruth receiving = truth_of(scene);
  int shadowed_box = 0;
  for (std::size_t p = 0; p < receiving.object.size(); ++p)
    shadowed_box += receiving.object[p] == int(kBox) && receiving.shadow[p] == 1;
  ASSERT_GT(shadowed_box, 100) << "the plate no longer shadows the box's top";
  scene.objects[kBox].receives_shadow = false;
  const gs::GroundTruth refusing = truth_of(scene);
  int box_pixels = 0, floor_shadow = 0;
  for (std::size_t p = 0; p < refusing.object.size(); ++p) {
    if (refusing.object[p] == int(kBox)) {
      ++box_pixels;
      EXPECT_EQ(refusing.shadow[p], 0);
      EXPECT_EQ(refusing.self_shadow[p], 0);
      EXPECT_NE(refusing.reach[p], gs::LightReach::Blocked);
    }
    if (refusing.object[p] == int(kFloor)) floor_shadow += refusing.shadow[p];
  }
  EXPECT_GT(box_pixels, 500);
  EXPECT_GT(floor_shadow, 500) << "the box and plate still shadow the floor";
  EXPECT_NE(plate, int(kBox));
  // The image agrees: the box's top is as bright as with nothing above it.
  gs::Scene alone = box_over_floor();
  const gs::GroundTruth unblocked = truth_of(alone);
  int compared = 0;
  for (std::size_t p = 0; p < refusing.object.size(); ++p) {
    if (refusing.object[p] != int(kBox) || unblocked.object[p] != int(kBox)) continue;
    for (int c = 0; c < 3; ++c) EXPECT_EQ(refusing.rgb[3 * p + c], unblocked.rgb[3 * p + c]);
    ++compared;
  }
  EXPECT_GT(compared, 500);
}

// The techniques cull back faces, so the truth does too: from below, the one-sided floor is not
// there and the box's bottom shows through it.
TEST(GroundTruthTest, SurfacesSeenFromBehindAreInvisible) {
  gs::Scene scene = box_over_floor();
  scene.camera.position = {0, -3, 6};
  scene.camera.target = {0, 1, 0};
  const gs::GroundTruth truth = truth_of(scene);
  EXPECT_EQ(std::count(truth.object.begin(), truth.object.end(), int(kFloor)), 0);
  EXPECT_GT(std::count(truth.object.begin(), truth.object.end(), int(kBox)), 500);
}

TEST(GroundTruthTest, SameSceneSameBytes) {
  gs::Scene scene = box_over_floor();
  scene.objects.push_back(object("plate", gs::make_plane(0.6f, 1), {0, 3.5f, 0}));
  const gs::GroundTruth a = truth_of(scene), b = truth_of(scene);
  EXPECT_EQ(a.object, b.object);
  EXPECT_TRUE(a.reach == b.reach);
  EXPECT_EQ(a.shadow, b.shadow);
  EXPECT_EQ(a.self_shadow, b.self_shadow);
  EXPECT_EQ(a.rgb, b.rgb);
}

TEST(GroundTruthTest, RefusesAbsurdSizes) {
  gs::Scene scene = box_over_floor();
  scene.width = scene.height = 100000;
  gs::GroundTruth truth;
  std::string error;
  EXPECT_FALSE(gs::compute_ground_truth(scene, truth, error));
  EXPECT_NE(error.find("100000"), std::string::npos) << error;
  EXPECT_TRUE(truth.object.empty()) << "left unchanged";
  scene.width = 0, scene.height = 240;
  EXPECT_FALSE(gs::compute_ground_truth(scene, truth, error));
}

TEST(GroundTruthTest, SkipsDegenerateTriangles) {
  gs::Scene scene = box_over_floor();
  gs::Mesh &box = scene.objects[kBox].mesh;
  const glm::uvec3 first = box.triangles[0];
  box.triangles.push_back({first.x, first.x, first.y});  // zero area
  const gs::GroundTruth with = truth_of(scene);
  box.triangles.pop_back();
  const gs::GroundTruth without = truth_of(scene);
  EXPECT_EQ(with.object, without.object);
  EXPECT_EQ(with.shadow, without.shadow);
  EXPECT_EQ(with.rgb, without.rgb);
}

// Prints the time the truth takes on a full fight frame (for the reader; nothing asserts it).
TEST(GroundTruthTest, FightSceneHasCastShadow) {
  gs::FightScene fight(640, 480, 256);
  const gs::Scene &scene = fight.at(2.0f);
  gs::GroundTruth truth;
  std::string error;
  const auto start = std::chrono::steady_clock::now();
  ASSERT_TRUE(gs::compute_ground_truth(scene, truth, error)) << error;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "ground truth, fight scene 640x480: " << seconds << " s, " << count(truth.shadow)
            << " shadow pixels, " << count(truth.self_shadow) << " self-shadow pixels\n";
  EXPECT_GT(count(truth.shadow), 0);
}

}  // namespace

// A light lying in the floor's plane reaches none of it: facing is decided per face, as the
// techniques decide it (edge-on is away), not from each hit point, whose rounding off the plane
// once lit a random scatter of the floor and called 1.6% of the pixels shadow where every
// technique drew none (audit x5). Every floor pixel is Outside, none shadowed.
TEST(GroundTruthTest, ALightInAFacesPlaneReachesNoneOfIt) {
  gs::Scene scene = box_over_floor();
  scene.lights[0].position = {-6.0f, 0.0f, 0.3f};
  scene.lights[0].target = {0.0f, 0.0f, 0.0f};
  scene.lights[0].cone_degrees = 100.0f;
  const gs::GroundTruth truth = truth_of(scene);
  int floor_pixels = 0;
  for (std::size_t p = 0; p < truth.object.size(); ++p) {
    if (truth.object[p] != int(kFloor)) continue;
    ++floor_pixels;
    EXPECT_EQ(truth.reach[p], gs::LightReach::Outside) << "pixel " << p;
    EXPECT_EQ(truth.shadow[p], 0) << "pixel " << p;
  }
  EXPECT_GT(floor_pixels, 1000);
}
