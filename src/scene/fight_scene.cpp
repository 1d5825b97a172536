// The fight, staged for its shadows: fighters face each other across the ring's centre line
// (x axis), feet on the mat's relief. A low spotlight stands behind the attacker, a little to
// the far side (-z) of the line, so the attacker's shadow runs across the mat towards the
// camera's side and climbs the near half of the other fighter; between the attacks it swings
// round the far side to the other end. The camera watches from the light's side, where the
// shadowed receiver faces it, and dollies in and out (so --auto-size has sizes to follow).
#include "scene/fight_scene.h"

#include "scene/fighter.h"
#include "scene/ring.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace gs {
namespace {

const glm::vec3 kBodyColors[2] = {{0.8f, 0.12f, 0.1f}, {0.16f, 0.34f, 0.95f}};  // bright: the shadow reads on them
constexpr float kStartX = 0.55f;  // each fighter's distance from the centre, metres: in reach

// Azimuths in degrees about the y axis, world: 0 looks from +z (the camera's side of the ring),
// -90 from -x (behind the red fighter), +/-180 from the far side.
constexpr float kLightAzimuthBehindRed = -97.0f;  // 7 degrees off the line, to the far side
constexpr float kLightSwing = -166.0f;            // to -263 = +97: behind blue, far side
constexpr float kLightDistance = 3.3f;             // from the centre, metres: past the ropes
constexpr float kLightHeight = 3.05f;              // world y; the mat is at about 1 m
constexpr float kCameraAzimuthRed = -40.0f;  // the camera's azimuth with the light at red
constexpr float kCameraSwing = 80.0f;
constexpr float kCameraHeight = 2.9f;        // about 1.9 m above the mat
// Camera distance from the centre, metres: close on the blows, back to see the whole ring
// while the light swings (inside the ropes at these azimuths either way).
constexpr float kCameraNear = 2.3f, kCameraFar = 4.3f;
constexpr float kCameraBackSeconds = 1.2f;  // before and after each swing's middle

// The light's swings (fight-loop seconds): to blue before blue steps in, back before the loop
// restarts with red's step (fighter.cpp's schedule).
constexpr float kSwingToBlue[2] = {3.1f, 3.7f};
constexpr float kSwingToRed[2] = {7.2f, 7.8f};

float eased(float t) {
  t = glm::clamp(t, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

glm::vec3 on_circle(float azimuth_degrees, float distance, float height) {
  const float a = glm::radians(azimuth_degrees);
  return {distance * std::sin(a), height, distance * std::cos(a)};
}

// 1 at the middle of a swing of the light, falling to 0 kCameraBackSeconds before and after.
float camera_back(float time) {
  const float loop = fight_loop_seconds();
  float back = 0.0f;
  for (const float *swing : {kSwingToBlue, kSwingToRed}) {
    float from_middle = std::fmod(std::abs(time - 0.5f * (swing[0] + swing[1])), loop);
    from_middle = std::min(from_middle, loop - from_middle);
    back = std::max(back, eased(1.0f - from_middle / kCameraBackSeconds));
  }
  return back;
}

}  // namespace

float fight_light_side(float time) {
  const float loop = fight_loop_seconds();
  float t = std::fmod(time, loop);
  if (!(t >= 0.0f)) t = t < 0.0f ? t + loop : 0.0f;  // negative times wrap; NaN: the start
  if (t < kSwingToBlue[0]) return 0.0f;
  if (t < kSwingToBlue[1]) return eased((t - kSwingToBlue[0]) / (kSwingToBlue[1] - kSwingToBlue[0]));
  if (t < kSwingToRed[0]) return 1.0f;
  return 1.0f - eased((t - kSwingToRed[0]) / (kSwingToRed[1] - kSwingToRed[0]));
}

FightScene::FightScene(int width, int height, int shadow_size) {
  scene_.width = width;
  scene_.height = height;
  scene_.ambient = glm::vec3(0.3f);
  scene_.background = glm::vec3(0.04f, 0.05f, 0.09f);
  SceneObject ring;
  ring.name = "ring";
  ring.mesh = build_ring();
  ring.casts_shadow = false;  // the posts and ropes would need their own textures; see docs
  scene_.objects.push_back(std::move(ring));
  for (int i = 0; i < 2; ++i) {
    SceneObject fighter;
    fighter.name = i == 0 ? "red fighter" : "blue fighter";
    scene_.objects.push_back(std::move(fighter));
  }
  SpotLight light;
  light.cone_degrees = 75.0f;
  light.color = glm::vec3(1.0f, 0.96f, 0.88f);
  light.shadow_size = shadow_size;
  scene_.lights.push_back(light);
  scene_.camera.fov_degrees = 50.0f;
  at(0.0f);
}

const Scene &FightScene::at(float time) {
  for (int i = 0; i < 2; ++i) {
    SceneObject &object = scene_.objects[kFighters[i]];
    const FighterPose pose = fight_loop_pose(i, time);
    // No simplified shadow_mesh: every technique casts from the mesh the eye sees (the 4-sided
    // limbs of build_fighter_lod cast a shadow up to 0.15% of the receiver pixels off the true
    // one, more than a pixel from its edge, on the fight frames).
    object.mesh = build_fighter(pose, kBodyColors[i]);
    // Model +z faces the opponent: fighter 0 looks along +x, fighter 1 along -x.
    const float side = i == 0 ? -1.0f : 1.0f;
    const float x = side * kStartX;
    const float facing = i == 0 ? glm::half_pi<float>() : -glm::half_pi<float>();
    const float floor_height = ring_mat_height(x, 0.0f);
    object.model_to_world = glm::rotate(glm::translate(glm::mat4(1.0f), {x, floor_height, 0.0f}),
                                        facing, glm::vec3(0, 1, 0));
  }
  const float side = fight_light_side(time);
  SpotLight &light = scene_.lights.front();
  light.position = on_circle(kLightAzimuthBehindRed + kLightSwing * side, kLightDistance, kLightHeight);
  light.target = {0.0f, 1.5f, 0.0f};
  const float distance = kCameraNear + (kCameraFar - kCameraNear) * camera_back(time);
  scene_.camera.position = on_circle(kCameraAzimuthRed + kCameraSwing * side, distance, kCameraHeight);
  scene_.camera.target = {0.0f, 1.85f, 0.0f};
  return scene_;
}

}  // namespace gs
